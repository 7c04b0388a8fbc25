#!/usr/bin/python3
"""Plot the collapse acceleration per direction from `polydem collapse`.

    polydem collapse DECK --direction 0 --direction 45 --direction 90 --out out/collapse
    scripts/plot_collapse.py out/collapse/collapse.json --out collapse.png
    scripts/plot_collapse.py out/dir0/collapse.json out/dir90/collapse.json out/ramp/collapse.json

Reads collapse.json: for each entry of `directions`, the azimuth of the ground
motion (`direction_deg`) and, by method, `bisection.collapse_acceleration_g`
(with its final `bracket_g`, drawn as an error bar) and
`ramp.collapse_acceleration_g` (the acceleration reached when a ramp at
`rate_g_per_s` collapsed the structure; it overshoots the static value by the
rate times the time the collapse takes to develop). A direction whose method
failed (`error`, or a null acceleration) is marked with an x on the axis.

--kind polar draws the accelerations against the azimuth (the default with three
or more directions), --kind bar groups them per direction. --hline G LABEL adds
a reference acceleration (an analytical value): a line on the bar chart, a
circle on the polar plot.

Several collapse.json files (one search per direction or per method, run one
after another or on different machines) are merged into one plot: the
directions of all files, each direction's methods from whichever file has
them (a later file wins when two have the same direction and method).

Uses only Debian's python3-numpy and python3-matplotlib.
"""

import argparse
import json
import math
import os

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

METHODS = [("bisection", "bisection (constant acceleration)", "tab:blue", "o"),
           ("ramp", "ramp", "tab:orange", "s")]


def read(paths):
    """The first file's document, the lowest acceleration of all, and the merged rows."""
    docs, by_deg = [], {}
    for path in paths:
        with open(path) as f:
            doc = json.load(f)
        docs.append(doc)
        for row in rows_of(doc):
            by_deg.setdefault(row["deg"], {}).update(row)
    rows = sorted(by_deg.values(), key=lambda r: r["deg"])
    if not rows:
        raise SystemExit(f"{' '.join(paths)}: no directions")
    lows = [float(d["collapse_acceleration_g"]) for d in docs if d.get("collapse_acceleration_g") is not None]
    return docs[0], (min(lows) if lows else None), rows


def rows_of(doc):
    rows = []
    for d in doc.get("directions", []):
        row = {"deg": float(d["direction_deg"])}
        for method, *_ in METHODS:
            m = d.get(method)
            if m is None:
                continue
            a = m.get("collapse_acceleration_g")
            row[method] = float(a) if a is not None else math.nan
            if m.get("rate_g_per_s") is not None:
                row[method + "_rate"] = float(m["rate_g_per_s"])
            if "bracket_g" in m:
                row[method + "_bracket"] = [float(b) for b in m["bracket_g"]]
        rows.append(row)
    return rows


def present(rows):
    """The methods of the rows, the ramp's label with its rate when all ramps share one."""
    out = []
    for method, label, color, marker in METHODS:
        if not any(method in r for r in rows):
            continue
        rates = {r[method + "_rate"] for r in rows if method + "_rate" in r}
        if len(rates) == 1:
            label += f" {rates.pop():g} g/s"
        out.append((method, label, color, marker))
    return out


def draw_hlines(ax, hlines, polar):
    """Reference accelerations: a line (bar chart) or a circle (polar)."""
    styles = ["-.", ":", "--"]
    for k, (g, label) in enumerate(hlines):
        style = dict(color="tab:brown" if k % 2 == 0 else "tab:green", ls=styles[k % len(styles)], lw=1.1,
                     label=f"{label}: {float(g):.3g} g", zorder=3)
        if polar:
            ax.plot(np.linspace(0.0, 2.0 * np.pi, 361), np.full(361, float(g)), **style)
        else:
            ax.axhline(float(g), **style)


def plot_bar(ax, rows):
    methods = present(rows)
    width = 0.8 / len(methods)
    x = np.arange(len(rows))
    top = max([r.get(m[0], 0.0) for r in rows for m in methods if np.isfinite(r.get(m[0], np.nan))] + [0.1])
    for k, (method, label, color, _) in enumerate(methods):
        xs = x + (k - (len(methods) - 1) / 2) * width
        values = np.array([r.get(method, np.nan) for r in rows])
        ok = np.isfinite(values)
        bars = ax.bar(xs[ok], values[ok], width * 0.92, color=color, label=label)
        ax.bar_label(bars, fmt="%.3f", fontsize=7, padding=2)
        brackets = [(i, r[method + "_bracket"]) for i, r in enumerate(rows) if method + "_bracket" in r]
        for i, (lo, hi) in brackets:
            ax.plot([xs[i], xs[i]], [lo, hi], color="black", lw=1.0)
        failed = ~ok & np.array([method in r for r in rows])
        if failed.any():
            ax.plot(xs[failed], np.zeros(failed.sum()), "x", color=color, ms=8, mew=2)
    ax.set_xticks(x, [f"{r['deg']:g}\u00b0" for r in rows])
    ax.set_xlabel("direction of the ground motion, azimuth [\u00b0]")
    ax.set_ylabel("collapse acceleration [g]")
    ax.set_ylim(0, 1.3 * top)
    ax.grid(True, axis="y", lw=0.4, alpha=0.5)
    ax.legend(fontsize=8, loc="upper center", ncol=2)


def plot_polar(ax, rows):
    degs = np.array([r["deg"] for r in rows])
    theta = np.radians(degs)
    top = 0.1
    for method, label, color, marker in present(rows):
        values = np.array([r.get(method, np.nan) for r in rows])
        ok = np.isfinite(values)
        if ok.any():
            top = max(top, float(np.nanmax(values)))
            ax.plot(theta[ok], values[ok], marker=marker, color=color, lw=1.2, ms=5, label=label)
        for i, r in enumerate(rows):
            if method + "_bracket" in r:
                lo, hi = r[method + "_bracket"]
                ax.plot([theta[i], theta[i]], [lo, hi], color="black", lw=1.0)
        failed = ~ok & np.array([method in r for r in rows])
        if failed.any():
            ax.plot(theta[failed], np.zeros(failed.sum()), "x", color=color, ms=8, mew=2)
    ax.set_rlim(0, 1.15 * top)
    ax.set_theta_zero_location("E")
    ax.set_theta_direction(1)
    low, high = 45.0 * np.floor(degs.min() / 45.0), 45.0 * np.ceil(degs.max() / 45.0)
    if high - low < 45.0:
        high = low + 45.0
    sector = high - low <= 180.0
    if sector:  # a sector is easier to read than a mostly empty circle
        ax.set_thetamin(low)
        ax.set_thetamax(high)
    ax.legend(fontsize=8, title="collapse acceleration [g]", title_fontsize=8, loc="upper left",
              bbox_to_anchor=(0.0, -0.08) if sector else (1.02, 1.0))


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("collapse", nargs="+", help="collapse.json written by polydem collapse (several: merged)")
    ap.add_argument("--kind", choices=["auto", "polar", "bar"], default="auto",
                    help="polar (three or more directions) or bar (default auto)")
    ap.add_argument("--out", help="PNG to write (default: collapse.png beside the first collapse.json)")
    ap.add_argument("--title", help="figure title (default: the deck and the lowest collapse acceleration)")
    ap.add_argument("--hline", nargs=2, action="append", default=[], metavar=("G", "LABEL"),
                    help="a reference acceleration in g with its label (repeatable; a circle in polar)")
    ap.add_argument("--dpi", type=int, default=110)
    args = ap.parse_args(argv)

    doc, lowest, rows = read(args.collapse)
    kind = args.kind if args.kind != "auto" else ("polar" if len(rows) >= 3 else "bar")
    fig = plt.figure(figsize=(7.0, 5.5))
    ax = fig.add_subplot(projection="polar" if kind == "polar" else None)
    if kind == "polar":
        draw_hlines(ax, args.hline, True)
        plot_polar(ax, rows)
    else:
        draw_hlines(ax, args.hline, False)
        plot_bar(ax, rows)

    title = args.title
    if title is None:
        title = f"collapse acceleration: {doc.get('deck', args.collapse[0])}"
        if lowest is not None:
            title += f"\nlowest {float(lowest):.3f} g"
    fig.suptitle(title, fontsize=11)
    fig.tight_layout()
    out = args.out or os.path.join(os.path.dirname(os.path.abspath(args.collapse[0])), "collapse.png")
    fig.savefig(out, dpi=args.dpi)
    plt.close(fig)
    print(f"wrote {out} ({len(rows)} directions, {kind})")


if __name__ == "__main__":
    main()
