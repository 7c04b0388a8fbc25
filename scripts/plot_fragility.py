#!/usr/bin/python3
"""Fragility curves with their bootstrap bands and the data points.

    scripts/plot_fragility.py DIR [--im-label 'PGA [g]'] [--out DIR/fragility.png]

DIR is the output of `polydem analytic fragility INPUT.csv --out DIR`
(docs/fragility.md), which runs this script itself unless --no-plot: its
fragility_parameters.csv, fragility_curves.csv and fragility_points.csv.
One colour per damage state (damaged, stones lost, collapsed): the fitted
lognormal curve (solid), its band (shaded) and the data. IDA: each record's
capacity as the empirical fraction of records reached by that IM (steps of
1/records, circles) and the records that never reached the state as crosses
at P = 0 at the largest IM they were run at. Stripes: the fraction of each
stripe's runs that reached the state (circles, area by the number of runs).
A state without a fit (none reached, all reached, not identified) shows its
data and names its status in the legend.

Uses only Debian's python3-numpy and python3-matplotlib.
"""
import argparse
import csv
import os

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

COLOURS = {"damaged": "tab:blue", "stones_lost": "tab:orange", "collapsed": "tab:red"}
LABELS = {"damaged": "damaged", "stones_lost": "stones lost", "collapsed": "collapsed"}


def rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("dir")
    ap.add_argument("--im-label", default="IM")
    ap.add_argument("--out", default=None, help="PNG (default DIR/fragility.png)")
    ap.add_argument("--title", default=None)
    ap.add_argument("--dpi", type=int, default=120)
    args = ap.parse_args()
    params = rows(os.path.join(args.dir, "fragility_parameters.csv"))
    curves = rows(os.path.join(args.dir, "fragility_curves.csv"))
    points = rows(os.path.join(args.dir, "fragility_points.csv"))
    fig, ax = plt.subplots(figsize=(7.0, 4.6))
    method = params[0]["method"] if params else "ida"
    for p in params:
        state, colour = p["state"], COLOURS.get(p["state"], "k")
        c = [r for r in curves if r["state"] == state]
        im = np.array([float(r["im"]) for r in c])
        label = LABELS.get(state, state)
        if p["status"] == "fitted":
            prob = np.array([float(r["probability"]) for r in c])
            low = np.array([float(r["low"]) for r in c])
            high = np.array([float(r["high"]) for r in c])
            label += " (theta %.3g, beta %.2f)" % (float(p["theta"]), float(p["beta"]))
            ax.plot(im, prob, color=colour, lw=2, label=label)
            if np.isfinite(low).any():
                ax.fill_between(im, low, high, color=colour, alpha=0.18, lw=0)
        else:
            ax.plot([], [], color=colour, lw=2, label=label + ": " + p["status"].replace("_", " "))
        pts = [r for r in points if r["state"] == state]
        if method == "ida":
            n = len(pts)
            cap = sorted(float(r["im"]) for r in pts if r["reached"] == "1")
            cen = [float(r["im"]) for r in pts if r["reached"] != "1"]
            if cap:
                ax.plot(cap, np.arange(1, len(cap) + 1) / n, "o", color=colour, ms=4, mfc="none")
            if cen:
                ax.plot(cen, np.zeros(len(cen)), "x", color=colour, ms=5)
        else:
            x = [float(r["im"]) for r in pts]
            y = [float(r["fraction"]) for r in pts]
            s = [12 + 4 * int(r["runs"]) for r in pts]
            ax.scatter(x, y, s=s, facecolors="none", edgecolors=colour)
    ax.set_xlabel(args.im_label)
    ax.set_ylabel("P(DS >= ds | IM)")
    ax.set_ylim(-0.03, 1.03)
    ax.set_xlim(left=0)
    ax.grid(True, alpha=0.3)
    conf = float(params[0]["confidence"]) if params else 0.9
    ax.set_title(args.title or "Lognormal fragility (%s fit), %g %% bootstrap bands"
                 % ("IDA" if method == "ida" else "multiple-stripe", 100 * conf))
    ax.legend(loc="lower right", fontsize=8)
    fig.tight_layout()
    out = args.out or os.path.join(args.dir, "fragility.png")
    fig.savefig(out, dpi=args.dpi)
    print("wrote", out)


if __name__ == "__main__":
    main()
