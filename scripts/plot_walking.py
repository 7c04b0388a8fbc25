#!/usr/bin/python3
"""Walking per course from ensembles: how far the joints of each course are
open, as the median and the 16-84 % band over the replicas, against height.

    scripts/plot_walking.py out/walk/courses.csv --out walking.png
    scripts/plot_walking.py out/eq/courses.csv --key ground_motion.scale --label "record x{}" \
        --compare out/eq_sf04/courses.csv "safety factor 0.4, x{}" --out walking.png

Reads courses.csv as `polydem ensemble` or `polydem sweep --replicas` writes it
with `output.walking = true` (docs/ensembles.md, "Result tables"): per course
its bed level and, per figure, the replicas' n, p16, median and p84. With
--key, the rows of each value of that key (a sweep's point) are one curve,
labelled by --label with the value put in for {}.

Two panels, vertical joints (left) and bed joints (right). Each curve is the
median over the replicas of the largest residual opening in each course
(solid, markers at the courses' bed levels, the 16-84 % band shaded) and of
the mean residual opening of its joints (dashed). --figure peak draws the
largest opening during the run instead (no mean). --compare CSV LABEL adds
another table's curves (another setting of the same ensemble) in grey
tones, dotted, with their bands as error bars.

Uses only Debian's python3-numpy and python3-matplotlib.
"""

import argparse
import csv

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_table(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        raise SystemExit(f"{path}: no courses (was the deck run with output.walking = true?)")
    return rows


def number(x):
    return float(x) if x not in ("", None) else np.nan


def curves(rows, key):
    """{point value or None: rows of that point, by course}"""
    out = {}
    for r in rows:
        v = number(r[key]) if key else None
        out.setdefault(v, []).append(r)
    for v in out:
        out[v].sort(key=lambda r: int(r["course"]))
    return out


def series(rows, stem):
    return tuple(np.array([number(r[f"{stem}_{s}"]) for r in rows]) for s in ("p16", "median", "p84"))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("courses", help="courses.csv of an ensemble or a sweep with --replicas")
    ap.add_argument("--key", help="the sweep key whose values are the curves (e.g. ground_motion.scale)")
    ap.add_argument("--label", default="{}", help="curve label, {} the key's value")
    ap.add_argument("--compare", nargs=2, metavar=("CSV", "LABEL"), help="another table's curves, dotted")
    ap.add_argument("--figure", choices=("residual", "peak"), default="residual")
    ap.add_argument("--title", default="")
    ap.add_argument("--unit", choices=("mm", "m"), default="mm")
    ap.add_argument("--dpi", type=int, default=110)
    ap.add_argument("--out", default="walking.png")
    args = ap.parse_args()

    scale = 1e3 if args.unit == "mm" else 1.0
    fig, axes = plt.subplots(1, 2, figsize=(11, 6), sharey=True)
    colours = plt.cm.viridis(np.linspace(0.0, 0.85, 6))
    greys = plt.cm.Greys(np.linspace(0.5, 0.9, 6))

    def draw(rows_by_point, label, dotted):
        for i, (value, rows) in enumerate(sorted(rows_by_point.items(), key=lambda kv: (kv[0] is None, kv[0]))):
            z = np.array([number(r["level_m"]) for r in rows])
            name = label.format(f"{value:g}" if value is not None else "")
            n = rows[0].get("residual_vertical_largest_m_n", "")
            for ax, kind in zip(axes, ("vertical", "bed")):
                stem = f"residual_{kind}_largest_m" if args.figure == "residual" else f"max_{kind}_m"
                lo, mid, hi = (s * scale for s in series(rows, stem))
                has = np.array([int(r[f"{kind}_joints"]) > 0 for r in rows])
                if not has.any():
                    continue
                c = greys[i % len(greys)] if dotted else colours[i % len(colours)]
                line = f"{name} (n = {n})"
                if dotted:
                    ax.errorbar(mid[has], z[has], xerr=[mid[has] - lo[has], hi[has] - mid[has]], fmt=":s",
                                color=c, ms=4, capsize=2, label=line + ", median, 16-84 %")
                else:
                    ax.fill_betweenx(z[has], lo[has], hi[has], color=c, alpha=0.2, lw=0)
                    ax.plot(mid[has], z[has], "-o", color=c, ms=4, label=line + ": largest, median, 16-84 %")
                    if args.figure == "residual":
                        mean = series(rows, f"residual_{kind}_mean_m")[1] * scale
                        ax.plot(mean[has], z[has], "--", color=c, lw=1, label=line + ": mean of the course, median")

    draw(curves(read_table(args.courses), args.key), args.label, False)
    if args.compare:
        draw(curves(read_table(args.compare[0]), args.key), args.compare[1], True)
    what = "residual opening" if args.figure == "residual" else "largest opening during the run"
    for ax, kind in zip(axes, ("vertical joints", "bed joints")):
        ax.set_xlabel(f"{what} [{args.unit}]")
        ax.set_title(kind)
        ax.grid(True, alpha=0.3)
        ax.set_xlim(left=0)
    axes[0].set_ylabel("course: its bed level [m]")
    axes[1].legend(fontsize=7, loc="best")
    if args.title:
        fig.suptitle(args.title)
    fig.tight_layout()
    fig.savefig(args.out, dpi=args.dpi)
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
