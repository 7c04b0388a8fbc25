#!/usr/bin/python3
"""Plot the histories of a polydem run against time, one panel per quantity.

    scripts/plot_histories.py out/main/results.h5
    scripts/plot_histories.py out/rock/results.h5 --columns 'pillar.rotation.y' 'pillar.angular_velocity.y'
    scripts/plot_histories.py out/main/results.h5 --columns '*.position.y' 'ground.*' --out wall.png

Reads /histories of results.h5 (docs/results.md): `time` and one column per
channel, named `<block>.<quantity>.<x|y|z>` (`walking.bed_opening`,
`walking.vertical_opening` and `ground.acceleration` have two parts). Columns
are grouped by quantity (`position`, `rotation`, `walking`, `ground`, ...): each
group is one panel, each column one line labelled by block and axis, and the
y axis carries the unit stored in the column's `unit` attribute.

--columns takes shell-style patterns (fnmatch) matched against the column
names; without it every column is plotted.

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


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("results", help="results.h5 written by polydem run")
    ap.add_argument("--columns", nargs="+", metavar="PATTERN",
                    help="history columns to plot (fnmatch patterns, e.g. 'pillar.rotation.*'); default all")
    ap.add_argument("--relative", action="store_true",
                    help="plot each column's change from its first sample (e.g. displacement instead of position)")
    ap.add_argument("--out", help="PNG to write (default: histories.png beside results.h5)")
    ap.add_argument("--title", help="figure title (default: the deck path stored in the file)")
    ap.add_argument("--dpi", type=int, default=110)
    args = ap.parse_args(argv)

    with h5py.File(args.results, "r") as f:
        if "histories" not in f or "time" not in f["histories"]:
            raise SystemExit(f"{args.results}: no /histories/time (the deck asked for no histories)")
        h = f["histories"]
        time = h["time"][:]
        time_unit = _text(h["time"].attrs.get("unit", "s"))
        names = sorted(n for n in h if n != "time")
        if args.columns:
            # In the order of the patterns, then of the names.
            chosen = [n for p in args.columns for n in names if fnmatch.fnmatchcase(n, p)]
            chosen = list(dict.fromkeys(chosen))
            if not chosen:
                raise SystemExit(f"{args.results}: no column matches {' '.join(args.columns)}; "
                                 f"columns: {' '.join(names)}")
            names = chosen
        columns = {n: (h[n][:], _text(h[n].attrs.get("unit", ""))) for n in names}
        deck = _text(f["deck"].attrs.get("path", "")) if "deck" in f else ""
    if not names:
        raise SystemExit(f"{args.results}: /histories holds only time")

    panels = {}  # quantity -> [(label, values, unit)], in first-seen order
    for n in names:
        key, label = group_of(n)
        panels.setdefault(key, []).append((label, *columns[n]))

    fig, axes = plt.subplots(len(panels), 1, sharex=True, squeeze=False,
                             figsize=(7.5, 1.0 + 2.1 * len(panels)))
    for ax, (key, lines) in zip(axes[:, 0], panels.items()):
        units = sorted({u for _, _, u in lines})
        for label, values, _ in lines:
            ax.plot(time, values - values[0] if args.relative else values, lw=1.1, label=label)
        name = f"change of {key}" if args.relative else key
        ax.set_ylabel(f"{name} [{', '.join(pretty_unit(u) for u in units)}]" if units != [""] else name)
        ax.grid(True, lw=0.4, alpha=0.5)
        ax.axhline(0.0, color="0.5", lw=0.5)
        if len(lines) > 1 or lines[0][0] != key.replace(" ", "."):
            ax.legend(fontsize=8, loc="best", ncol=min(3, len(lines)))
    axes[-1, 0].set_xlabel(f"time [{time_unit}]")
    axes[-1, 0].set_xlim(float(np.min(time)), float(np.max(time)))
    fig.suptitle(args.title if args.title is not None else f"histories: {deck or args.results}", fontsize=11)
    fig.tight_layout()
    out = args.out or os.path.join(os.path.dirname(os.path.abspath(args.results)), "histories.png")
    fig.savefig(out, dpi=args.dpi)
    plt.close(fig)
    print(f"wrote {out} ({len(names)} columns in {len(panels)} panels)")


if __name__ == "__main__":
    main()
