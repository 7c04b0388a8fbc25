#!/usr/bin/python3
"""Plot the histories of a polydem run against time, one panel per quantity.

    scripts/plot_histories.py out/main/results.h5
    scripts/plot_histories.py out/rock/results.h5 --columns 'pillar.rotation.y' 'pillar.angular_velocity.y'
    scripts/plot_histories.py out/main/results.h5 --columns '*.position.y' 'ground.*' --out wall.png
    scripts/plot_histories.py out/onset/results.h5 --columns 'pillar.rotation.y' --x ground.acceleration \
        --vline 0.25 'b/h = 0.25'
    scripts/plot_histories.py out/body/results.h5 out/kin/results.h5 --labels 'body force' 'kinematic' \
        --columns 'pillar.rotation.y' --difference

Reads /histories of results.h5 (docs/results.md): `time` and one column per
channel, named `<block>.<quantity>.<x|y|z>` (`walking.bed_opening`,
`walking.vertical_opening` and `ground.acceleration` have two parts). Columns
are grouped by quantity (`position`, `rotation`, `walking`, `ground`, ...): each
group is one panel, each column one line labelled by block and axis, and the
y axis carries the unit stored in the column's `unit` attribute.

--columns takes shell-style patterns (fnmatch) matched against the column
names; without it every column is plotted. --relative plots each column's
change from its first sample (a position becomes a displacement); --relative
PATTERN... only that of the columns that match.
--length-unit mm|um rescales the columns stored in m (drifts of a few um).

--x COLUMN plots against another column instead of time; the ground
acceleration (m/s^2) is then shown in g (9.81 m/s^2), the unit the decks use.
--vline X LABEL draws a labelled reference line across every panel at X (in
the units of the x axis).

Several results.h5 files are drawn over each other (the same columns of each,
the run named by --labels, default the deck file name); --difference (two
files) adds under each panel the second run minus the first, interpolated to
the first run's times, and writes its largest magnitude as a percentage of the
first run's largest value in the legend.

Uses only Debian's python3-numpy, python3-matplotlib and python3-h5py.
"""

import argparse
import fnmatch
import os

import h5py
import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

G = 9.81  # m/s^2, as polydem converts accelerations to g
LENGTH_SCALE = {"m": (1.0, "m"), "mm": (1e3, "mm"), "um": (1e6, "\u00b5m")}


def _text(value):
    return value.decode() if isinstance(value, bytes) else str(value)


def group_of(column):
    """(panel name, line label) for a history column name."""
    parts = column.split(".")
    if len(parts) >= 3:  # block.quantity.axis (a block name has no dots)
        return parts[-2].replace("_", " "), f"{'.'.join(parts[:-2])} {parts[-1]}"
    if parts[0] == "walking":  # walking.bed_opening, walking.vertical_opening: one panel
        return "joint opening", parts[-1].replace("_", " ")
    return column.replace(".", " ").replace("_", " "), column


def pretty_unit(unit):
    return unit.replace("^2", "\u00b2").replace("^3", "\u00b3")


def read_run(path, patterns, x_column):
    """time, {column: (values, unit)}, deck path of one results.h5 (the columns that match)."""
    with h5py.File(path, "r") as f:
        if "histories" not in f or "time" not in f["histories"]:
            raise SystemExit(f"{path}: no /histories/time (the deck asked for no histories)")
        h = f["histories"]
        time = h["time"][:]
        time_unit = _text(h["time"].attrs.get("unit", "s"))
        names = sorted(n for n in h if n != "time")
        if x_column is not None and x_column not in names:
            raise SystemExit(f"{path}: no column {x_column} for --x; columns: {' '.join(names)}")
        if patterns:
            # In the order of the patterns, then of the names.
            chosen = [n for p in patterns for n in names if fnmatch.fnmatchcase(n, p)]
            chosen = list(dict.fromkeys(chosen))
            if not chosen:
                raise SystemExit(f"{path}: no column matches {' '.join(patterns)}; columns: {' '.join(names)}")
            names = chosen
        if x_column is not None:
            names = [n for n in names if n != x_column]
            wanted = names + [x_column]
        else:
            wanted = names
        columns = {n: (h[n][:], _text(h[n].attrs.get("unit", ""))) for n in wanted}
        deck = _text(f["deck"].attrs.get("path", "")) if "deck" in f else ""
    if not names:
        raise SystemExit(f"{path}: /histories holds no column to plot")
    return time, time_unit, names, columns, deck


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("results", nargs="+", help="results.h5 written by polydem run (several: drawn over each other)")
    ap.add_argument("--columns", nargs="+", metavar="PATTERN",
                    help="history columns to plot (fnmatch patterns, e.g. 'pillar.rotation.*'); default all")
    ap.add_argument("--relative", nargs="*", metavar="PATTERN",
                    help="plot each column's change from its first sample (e.g. displacement instead of position);"
                         " with patterns, only the columns that match")
    ap.add_argument("--length-unit", choices=sorted(LENGTH_SCALE), default="m",
                    help="unit for the columns stored in m (default m)")
    ap.add_argument("--x", metavar="COLUMN",
                    help="plot against this column instead of time (ground.acceleration is shown in g)")
    ap.add_argument("--vline", nargs=2, action="append", default=[], metavar=("X", "LABEL"),
                    help="a labelled vertical reference line at X, in the x axis' unit (repeatable)")
    ap.add_argument("--labels", nargs="+", metavar="LABEL", help="one name per results file (for the legend)")
    ap.add_argument("--difference", action="store_true",
                    help="with two results files: add the second minus the first under each panel")
    ap.add_argument("--out", help="PNG to write (default: histories.png beside the first results.h5)")
    ap.add_argument("--title", help="figure title (default: the deck path stored in the file)")
    ap.add_argument("--dpi", type=int, default=110)
    args = ap.parse_args(argv)
    if args.labels and len(args.labels) != len(args.results):
        raise SystemExit(f"--labels: {len(args.labels)} labels for {len(args.results)} results files")
    if args.difference and len(args.results) != 2:
        raise SystemExit("--difference needs exactly two results files")

    runs = [read_run(path, args.columns, args.x) for path in args.results]
    names = runs[0][2]
    labels = args.labels or [os.path.basename(deck) or path for path, (_, _, _, _, deck) in zip(args.results, runs)]
    scale, length_unit = LENGTH_SCALE[args.length_unit]

    def x_of(run):
        time, time_unit, _, columns, _ = run
        if args.x is None:
            return time, f"time [{time_unit}]"
        values, unit = columns[args.x]
        if args.x == "ground.acceleration" and unit == "m/s^2":
            return values / G, "ground acceleration [g]"
        if unit == "m":
            return values * scale, f"{group_of(args.x)[0]} [{length_unit}]"
        return values, f"{group_of(args.x)[0]} [{pretty_unit(unit)}]" if unit else group_of(args.x)[0]

    def relative(column):
        if args.relative is None:
            return False
        return not args.relative or any(fnmatch.fnmatchcase(column, p) for p in args.relative)

    def y_of(column, values, unit):
        v = values - values[0] if relative(column) else values
        return (v * scale, length_unit) if unit == "m" else (v, pretty_unit(unit))

    panels = {}  # quantity -> [column], in first-seen order
    for n in names:
        panels.setdefault(group_of(n)[0], []).append(n)

    rows = []  # (kind, key): one panel per quantity, and its difference under it
    for key in panels:
        rows.append(("values", key))
        if args.difference:
            rows.append(("difference", key))
    heights = [1.0 if kind == "values" else 0.55 for kind, _ in rows]
    fig, axes = plt.subplots(len(rows), 1, sharex=True, squeeze=False,
                             figsize=(7.5, 1.0 + 2.1 * sum(heights)), gridspec_kw=dict(height_ratios=heights))
    styles = ["-", "--", ":", "-."]
    x_label = None
    for ax, (kind, key) in zip(axes[:, 0], rows):
        units = set()
        nlines = 0
        for n in panels[key]:
            axis_label = group_of(n)[1]
            if kind == "values":
                for k, run in enumerate(runs):
                    if n not in run[3]:
                        continue
                    x, x_label = x_of(run)
                    y, unit = y_of(n, *run[3][n])
                    units.add(unit)
                    label = axis_label if len(runs) == 1 else f"{labels[k]}: {axis_label}"
                    # Several runs: one colour per run and column, the runs after the first dashed.
                    color = f"C{(k * len(panels[key]) + panels[key].index(n)) % 10}" if len(runs) > 1 else None
                    ax.plot(x, y, lw=1.1 if k == 0 else 1.6, ls=styles[k % len(styles)], label=label, color=color)
                    nlines += 1
            else:
                if n not in runs[1][3]:
                    continue
                x0, x_label = x_of(runs[0])
                y0, unit = y_of(n, *runs[0][3][n])
                y1, _ = y_of(n, *runs[1][3][n])
                t0, t1 = runs[0][0], runs[1][0]
                d = np.interp(t0, t1, y1) - y0
                peak = float(np.max(np.abs(y0))) if y0.size else 0.0
                share = f", largest {100.0 * np.max(np.abs(d)) / peak:.2g} % of the peak" if peak > 0 else ""
                units.add(unit)
                ax.plot(x0, d, lw=1.1, color="0.15" if len(panels[key]) == 1 else f"C{panels[key].index(n)}",
                        label=f"{axis_label}{share}")
                nlines += 1
        name = key if kind == "values" else f"{labels[1]} \u2212 {labels[0]}"
        if kind == "values" and all(relative(n) for n in panels[key]):
            name = f"change of {key}"
        units.discard("")
        ax.set_ylabel(f"{name} [{', '.join(sorted(units))}]" if units else name,
                      fontsize=10 if kind == "values" else 8)
        ax.grid(True, lw=0.4, alpha=0.5)
        ax.axhline(0.0, color="0.5", lw=0.5)
        for k, (value, text) in enumerate(args.vline):
            ax.axvline(float(value), color=("tab:red", "tab:purple", "tab:brown")[k % 3],
                       ls=("--", "-.", ":")[k % 3], lw=1.0, label=text if ax is axes[0, 0] else None)
        if nlines > 1 or len(runs) > 1 or kind == "difference" or args.vline or \
                group_of(panels[key][0])[1] != key.replace(" ", "."):
            ax.legend(fontsize=8, loc="best", ncol=min(3, max(1, nlines)))
    axes[-1, 0].set_xlabel(x_label)
    x_all = np.concatenate([x_of(run)[0] for run in runs])
    if args.x is None:
        axes[-1, 0].set_xlim(float(np.min(x_all)), float(np.max(x_all)))
    deck = runs[0][4]
    fig.suptitle(args.title if args.title is not None else f"histories: {deck or args.results[0]}", fontsize=11)
    fig.tight_layout()
    out = args.out or os.path.join(os.path.dirname(os.path.abspath(args.results[0])), "histories.png")
    fig.savefig(out, dpi=args.dpi)
    plt.close(fig)
    print(f"wrote {out} ({len(names)} columns in {len(panels)} panels, {len(runs)} run(s))")


if __name__ == "__main__":
    main()
