#!/usr/bin/python3
"""Collapse diagram for one-sine pulses: the analytical curve with DEM points.

    scripts/plot_collapse_diagram.py docs/data/spire_dem_collapse.csv \
        --polydem build/polydem --body shell --r_b 1.064 --H 9.4 \
        --out docs/img/spire_collapse_diagram.png

The analytical curve (rigid rocking body, eq. 7 and 10, Zhang & Makris 2001)
comes from `polydem analytic collapse-diagram --body BODY --r_b --H ... --json`
on a fine grid of T_p: the lower Mode I loop is shaded, its lower edge is the
minimum overturning amplitude, Mode II is above the upper curve; the dotted
line is the uplift acceleration tan(alpha). The DEM points come from CSVs of
`polydem sweep ... --search ground_motion.acceleration_g=...` (its
boundaries.csv, or the sweep's directory), given as positional
arguments (label "DEM") or as --dem CSV LABEL; the first set has filled
markers, the second open ones: the lowest damaging amplitude (triangle down),
the lowest collapsing one (circle: Mode I, square: Mode II) and, from
`transitions`, the start of Mode II above a Mode I loop (diamond) and the top
of a Mode I loop that closes before it (x). --hline G LABEL adds a reference
line. --restitution adds the analytical curve with that coefficient of
restitution (dashed) to the eq. 10 one (its Mode II boundary is the same: no
impact comes before it). --no-return adds the analytical curves under the
no-return convention (`polydem analytic collapse-diagram --no-return`:
overturned once past alpha with no way back), dash-dotted.

With --bands DIR LABEL (repeatable; one panel each, side by side), DIR is a
`polydem sweep --replicas N --band-axis ground_motion.acceleration_g`
directory (its bands.csv and ensembles.csv, docs/ensembles.md), or the
X.csv of a pair X.csv, X_points.csv that scripts/bands_refine.py merge
wrote: each point
of the grid is drawn as a square shaded by its observed probability of
collapse, the fitted 50 % collapse boundary as a line with its 16-84 % band
shaded, the 50 % damage and stones-lost boundaries as lines, and the
lowest amplitude at which half the replicas or more collapsed in Mode II
(open squares). A column
without a fit (a step sharper than the grid) is drawn at the middle of the
grid values that bracket its 50 % point (open marker), the bracket as its
band; a column where no replica collapsed gets a triangle at the top.

    scripts/plot_collapse_diagram.py --polydem build/polydem --body cone --r_b 0.4301 --H 3.4 \
        --bands out/tip_bands "deck" --bands out/tip_bands_rigid "rigid-like" --no-return \
        --out docs/img/tip_collapse_bands.png

Uses only Debian's python3-numpy and python3-matplotlib.
"""

import argparse
import csv
import json
import os
import subprocess

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import PatchCollection  # noqa: E402
from matplotlib.patches import Rectangle  # noqa: E402


def analytic(args, restitution=None, no_return=False):
    cmd = [args.polydem, "analytic", "collapse-diagram", "--body", args.body,
           "--r_b", str(args.r_b), "--H", str(args.H),
           "--Tp_min", str(args.Tp_min), "--Tp_max", str(args.Tp_max),
           "--Tp_count", str(args.Tp_count), "--a_max", str(args.a_max),
           "--points", str(args.points), "--json"]
    if restitution is not None:
        cmd += ["--restitution", str(restitution)]
    if no_return:
        cmd += ["--no-return"]
    out = subprocess.run(cmd, check=True, stdout=subprocess.PIPE, text=True).stdout
    return json.loads(out)


# polydem sweep's boundaries.csv names its columns after the deck keys.
SWEEP_COLUMNS = {"ground_motion.period": "T_p_s",
                 "damage_ground_motion.acceleration_g": "a_p_damage_g",
                 "collapse_ground_motion.acceleration_g": "a_p_collapse_g",
                 "collapse_mode": "mode"}


def read_dem(path):
    """Thresholds per T_p from a polydem sweep boundaries.csv (or a directory
    holding one), or from a CSV with columns T_p_s, a_p_damage_g,
    a_p_collapse_g, mode, transitions."""
    if os.path.isdir(path):
        path = os.path.join(path, "boundaries.csv")
    rows = []
    with open(path) as f:
        for r in csv.DictReader(f):
            r = {SWEEP_COLUMNS.get(k, k): v for k, v in r.items()}
            def num(key):
                v = r.get(key, "")
                return float(v) if v not in ("", None) else np.nan
            trans = []
            for item in filter(None, (r.get("transitions") or "").split(";")):
                a, change = item.split(":")
                below, above = change.split(">")
                trans.append((float(a), below, above))
            rows.append({"T": float(r["T_p_s"]), "damage": num("a_p_damage_g"),
                         "collapse": num("a_p_collapse_g"), "mode": r.get("mode", ""),
                         "transitions": trans})
    return rows


def curves(doc):
    T, low, mode2 = [], [], []
    loops = []
    for c in doc["columns"]:
        T.append(c["T_p_s"])
        low.append(c["min_collapse_g"] if c["min_collapse_g"] is not None else np.nan)
        m2 = c.get("mode2_boundary_g")
        mode2.append(m2 if m2 is not None else np.nan)
        loops.append(c.get("mode1_intervals_g") or [])
    return np.array(T), np.array(low, float), np.array(mode2, float), loops


def draw_analytic(ax, doc, label, style, shade, mode2_label="Mode II above, analytical"):
    T, low, mode2, loops = curves(doc)
    if shade:
        dT = (T[-1] - T[0]) / max(1, len(T) - 1)
        first = True
        for t, ivs in zip(T, loops):
            for lo, hi in ivs:
                ax.bar(t, hi - lo, bottom=lo, width=dT, color="tab:orange", alpha=0.25,
                       linewidth=0, label="Mode I region (analytical)" if first else None)
                first = False
    ax.plot(T, low, style, color="k", lw=1.5,
            label=f"minimum overturning, {label}")
    if mode2_label:  # the Mode II boundary does not depend on the restitution
        ax.plot(T, mode2, style, color="tab:red", lw=1.2, label=mode2_label)


def draw_dem(ax, rows, label, color, dcolor, ms, fill, ymax):
    T = np.array([r["T"] for r in rows])
    dmg = np.array([r["damage"] for r in rows])
    mfc = None if fill == "full" else "none"
    ax.plot(T, dmg, "v", color=dcolor, ms=ms, mfc=mfc, label=f"{label}: lowest damaging a_p")
    for mode, marker, name in (("I", "o", "Mode I"), ("II", "s", "Mode II")):
        sel = [r for r in rows if r["mode"] == mode and not np.isnan(r["collapse"])]
        if sel:
            ax.plot([r["T"] for r in sel], [r["collapse"] for r in sel], marker,
                    color=color, ms=ms, mfc=mfc,
                    label=f"{label}: lowest collapsing a_p ({name})")
    m2 = [(r["T"], a) for r in rows for a, lo, hi in r["transitions"]
          if hi == "II" and lo != "II" and a > r["collapse"]]
    if m2:
        ax.plot(*zip(*m2), "D", color=color, ms=ms - 1, mfc="none" if fill == "full" else color,
                label=f"{label}: Mode II from")
    tops = [(r["T"], a) for r in rows for a, lo, hi in r["transitions"]
            if lo == "I" and hi in ("intact", "damaged")]
    if tops:
        ax.plot(*zip(*tops), "x", color=color, ms=ms,
                label=f"{label}: top of a Mode I loop")
    nocol = [r["T"] for r in rows if np.isnan(r["collapse"])]
    if nocol:
        ax.plot(nocol, [ymax * 0.98] * len(nocol), "^", mfc="none", color=color,
                ms=ms, label=f"{label}: no collapse in the scan")


def read_csv_rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def cell(r, key):
    v = r.get(key, "")
    return float(v) if v not in ("", None) else np.nan


def read_bands(path, axis="ground_motion.acceleration_g", column="ground_motion.period"):
    """The bands of a `polydem sweep --replicas --band-axis` directory (its
    bands.csv and ensembles.csv), or of X.csv and X_points.csv as
    scripts/bands_refine.py merge writes them: per outcome, the columns (T,
    50 %, band low, band high, fitted), and the grid points with their
    observed probabilities."""
    if os.path.isdir(path):
        bands_csv, points_csv = os.path.join(path, "bands.csv"), os.path.join(path, "ensembles.csv")
    else:
        bands_csv, points_csv = path, os.path.splitext(path)[0] + "_points.csv"
    out = {}
    for r in read_csv_rows(bands_csv):
        T = float(r[column])
        fitted = r["status"] == "fitted"
        if fitted:
            mid, lo, hi = cell(r, axis + "_50"), cell(r, axis + "_16"), cell(r, axis + "_84")
        else:  # the grid values around the observed 50 % point
            lo, hi = cell(r, axis + "_below"), cell(r, axis + "_above")
            mid = 0.5 * (lo + hi)
        out.setdefault(r["outcome"], []).append(
            {"T": T, "mid": mid, "lo": lo, "hi": hi, "fitted": fitted, "status": r["status"],
             "undetermined": int(r["undetermined"])})
    points = [{"T": float(r[column]), "a": float(r[axis]), "p_collapse": cell(r, "p_collapse"),
               "p_damage": cell(r, "p_damage"), "judged": int(r["judged"]), "n_mode_II": int(r["n_mode_II"])}
              for r in read_csv_rows(points_csv)]
    return out, points


def draw_bands(ax, bands, points, ymax):
    """One set of DEM bands: P(collapse) squares, the collapse 50 % line and
    its 16-84 % band, the damage and stones-lost 50 % lines."""
    Ts = sorted({p["T"] for p in points})
    dT = 0.8 * min(np.diff(Ts)) if len(Ts) > 1 else 0.08
    cells = []
    for T in Ts:  # each column tiled: a point's cell spans halfway to its neighbours
        col = sorted((p for p in points if p["T"] == T), key=lambda p: p["a"])
        a = np.array([p["a"] for p in col])
        edges = np.concatenate(([a[0] - 0.5 * (a[1] - a[0]) if len(a) > 1 else a[0] - 0.05],
                                0.5 * (a[1:] + a[:-1]),
                                [a[-1] + 0.5 * (a[-1] - a[-2]) if len(a) > 1 else a[-1] + 0.05]))
        for p, lo, hi in zip(col, edges[:-1], edges[1:]):
            cells.append((p, Rectangle((T - dT / 2, lo), dT, hi - lo)))
    points = [p for p, _ in cells]
    cells = [c for _, c in cells]
    # Greys up to 2: P = 1 is a mid grey, under the lines drawn over it.
    sq = PatchCollection(cells, cmap="Greys", linewidths=0, zorder=1)
    sq.set_array(np.array([p["p_collapse"] for p in points]))
    sq.set_clim(0, 2.0)
    ax.add_collection(sq)
    col = sorted(bands.get("collapse", []), key=lambda r: r["T"])
    T = np.array([r["T"] for r in col])
    lo = np.array([r["lo"] for r in col])
    hi = np.array([r["hi"] for r in col])
    mid = np.array([r["mid"] for r in col])
    ax.fill_between(T, lo, hi, color="tab:blue", alpha=0.25, linewidth=0, zorder=2,
                    label="DEM collapse, 16-84 % (or the grid bracket)")
    ax.plot(T, mid, "-", color="tab:blue", lw=1.6, zorder=3, label="DEM collapse, 50 %")
    fit = np.array([r["fitted"] for r in col], bool)
    ax.plot(T[fit], mid[fit], "o", color="tab:blue", ms=5, zorder=4)
    ax.plot(T[~fit], mid[~fit], "o", color="tab:blue", mfc="white", ms=5, zorder=4,
            label="no fit: step within the grid, its middle")
    never = [r["T"] for r in col if r["status"] == "none_reached"]
    if never:
        ax.plot(never, [ymax * 0.98] * len(never), "^", color="tab:blue", mfc="none", ms=6,
                label="DEM: no collapse in the grid")
    mode2 = []
    for T in Ts:  # the lowest a_p at which half the judged replicas or more collapsed in Mode II
        col = sorted((p for p in points if p["T"] == T and p["judged"] > 0), key=lambda p: p["a"])
        first = [p["a"] for p in col if 2 * p["n_mode_II"] >= p["judged"]]
        if first:
            mode2.append((T, first[0]))
    if mode2:
        ax.plot(*zip(*mode2), "s", color="tab:red", mfc="none", ms=5, zorder=4,
                label="DEM: Mode II for half or more, from")
    for name, color, style, label in (("stones_lost", "tab:purple", "--", "DEM stones lost, 50 %"),
                                      ("damage", "tab:green", "-", "DEM damage, 50 %")):
        rows = sorted(bands.get(name, []), key=lambda r: r["T"])
        ax.plot([r["T"] for r in rows], [r["mid"] for r in rows], style, marker="v", ms=4,
                color=color, lw=1.2, zorder=3, label=label)
    return sq


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("csv", nargs="*", help="boundaries.csv of polydem sweep (or its directory)")
    ap.add_argument("--dem", nargs=2, action="append", default=[], metavar=("CSV", "LABEL"),
                    help="a CSV with its legend label (repeatable; second set: open markers)")
    ap.add_argument("--hline", nargs=2, action="append", default=[], metavar=("G", "LABEL"),
                    help="a horizontal reference line at G (repeatable)")
    ap.add_argument("--polydem", default="build/polydem")
    ap.add_argument("--body", default="cone", help="cone | shell (polydem analytic)")
    ap.add_argument("--r_b", type=float, default=0.4301)
    ap.add_argument("--H", type=float, default=3.4)
    ap.add_argument("--Tp_min", type=float, default=0.3)
    ap.add_argument("--Tp_max", type=float, default=2.2)
    ap.add_argument("--Tp_count", type=int, default=96)
    ap.add_argument("--a_max", type=float, default=3.5)
    ap.add_argument("--points", type=int, default=120)
    ap.add_argument("--y_max", type=float, default=None, help="top of the a_p axis [g]")
    ap.add_argument("--restitution", type=float, default=None,
                    help="also draw the analytical curve with this restitution")
    ap.add_argument("--no-return", action="store_true",
                    help="also draw the analytical curves under the no-return convention")
    ap.add_argument("--bands", nargs=2, action="append", default=[], metavar=("DIR", "LABEL"),
                    help="a polydem sweep --replicas --band-axis directory (repeatable; a panel each)")
    ap.add_argument("--out", default="collapse_diagram.png")
    ap.add_argument("--title", default=None)
    ap.add_argument("--dpi", type=int, default=150)
    args = ap.parse_args()

    doc = analytic(args)
    prop = doc["properties"]
    if args.bands:
        return plot_bands(args, doc)
    fig, ax = plt.subplots(figsize=(11, 5.4))
    c = prop["restitution"]
    draw_analytic(ax, doc, f"analytical (c = {c:.2f})", "-", True)
    if args.no_return:
        draw_analytic(ax, analytic(args, no_return=True), "analytical, no return", "-.", False,
                      "Mode II above, analytical, no return")
    if args.restitution is not None:
        draw_analytic(ax, analytic(args, args.restitution),
                      f"analytical (c = {args.restitution:.2f})", "--", False, None)
    ax.axhline(prop["uplift_g"], color="0.4", ls=":", lw=1,
               label=f"uplift, tan α = {prop['uplift_g']:.3f} g")

    for g, label in args.hline:
        ax.axhline(float(g), color="tab:brown", ls="-.", lw=1, label=label)
    dems = [(path, "DEM") for path in args.csv] + [tuple(d) for d in args.dem]
    styles = [("tab:blue", "tab:green", 7, "full"), ("tab:purple", "tab:olive", 5, "none")]
    for n, (path, label) in enumerate(dems):
        color, dcolor, ms, fill = styles[n % len(styles)]
        draw_dem(ax, read_dem(path), label, color, dcolor, ms, fill, args.y_max or args.a_max)

    body = doc["body"]
    ax.set_xlabel("pulse period T_p [s]")
    ax.set_ylabel("pulse amplitude a_p / g")
    ax.set_xlim(args.Tp_min, args.Tp_max)
    ax.set_ylim(0, args.y_max or args.a_max)
    kind = {"cone": "solid cone", "shell": "conical shell"}.get(body["kind"], body["kind"])
    ax.set_title(args.title or
                 f"One-sine pulse: {kind} r_b = {body['r_b_m']} m, H = {body['H_m']} m, "
                 f"p = {prop['p_rad_s']:.2f} rad/s", fontsize=10)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7.5, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    fig.tight_layout()
    fig.savefig(args.out, dpi=args.dpi)
    print(args.out)


def plot_bands(args, doc):
    """One panel per --bands set, the analytical curves on each."""
    prop = doc["properties"]
    no_return = analytic(args, no_return=True) if args.no_return else None
    restituted = analytic(args, args.restitution) if args.restitution is not None else None
    n = len(args.bands)
    # The legend and colour bar keep 3.1 in on the right whatever the panels.
    width = 6.2 * n + 3.1
    right = 1 - 2.95 / width
    fig, axes = plt.subplots(1, n, figsize=(width, 5.6), sharey=True, squeeze=False)
    ymax = args.y_max or args.a_max
    sq = None
    for ax, (directory, label) in zip(axes[0], args.bands):
        bands, points = read_bands(directory)
        sq = draw_bands(ax, bands, points, ymax)
        draw_analytic(ax, doc, f"|θ| > α (c = {prop['restitution']:.2f})", "-", True,
                      "Mode II above, |θ| > α")
        if no_return is not None:
            draw_analytic(ax, no_return, "no return", "-.", False, "Mode II above, no return")
        if restituted is not None:
            draw_analytic(ax, restituted, f"|θ| > α (c = {args.restitution:.2f})", "--", False, None)
        ax.axhline(prop["uplift_g"], color="0.4", ls=":", lw=1,
                   label=f"uplift, tan α = {prop['uplift_g']:.3f} g")
        for k, (g, text) in enumerate(args.hline or []):
            ax.axhline(float(g), color=f"C{k + 4}", ls="--", lw=1, label=text)
        ax.set_xlim(args.Tp_min, args.Tp_max)
        ax.set_ylim(0, ymax)
        ax.set_xlabel("pulse period T_p [s]")
        ax.set_title(label, fontsize=10)
        ax.grid(alpha=0.3)
    axes[0][0].set_ylabel("pulse amplitude a_p / g")
    handles, labels = axes[0][-1].get_legend_handles_labels()
    fig.legend(handles, labels, fontsize=7.5, loc="upper left", bbox_to_anchor=(right + 0.01, 0.93))
    cbar = fig.colorbar(sq, cax=fig.add_axes([right + 0.02, 0.12, 0.012, 0.28]))
    cbar.set_label("DEM: observed P(collapse) of the point", fontsize=8)
    cbar.set_ticks([0, 0.5, 1])
    cbar.ax.set_ylim(0, 1)
    if args.title:
        fig.suptitle(args.title, fontsize=10)
    fig.subplots_adjust(left=0.6 / width, right=right, bottom=0.1, top=0.88, wspace=0.06)
    fig.savefig(args.out, dpi=args.dpi)
    print(args.out)


if __name__ == "__main__":
    main()
