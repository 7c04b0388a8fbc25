#!/usr/bin/python3
"""Collapse diagram for one-sine pulses: the analytical curve with DEM points.

    scripts/plot_collapse_diagram.py docs/data/tip_dem_collapse.csv \
        --polydem build/polydem --body cone --r_b 0.4301 --H 3.4 \
        --out docs/img/tip_collapse_diagram.png

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
impact comes before it).

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


def analytic(args, restitution=None):
    cmd = [args.polydem, "analytic", "collapse-diagram", "--body", args.body,
           "--r_b", str(args.r_b), "--H", str(args.H),
           "--Tp_min", str(args.Tp_min), "--Tp_max", str(args.Tp_max),
           "--Tp_count", str(args.Tp_count), "--a_max", str(args.a_max),
           "--points", str(args.points), "--json"]
    if restitution is not None:
        cmd += ["--restitution", str(restitution)]
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


def draw_analytic(ax, doc, label, style, shade):
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
    if shade:  # the Mode II boundary does not depend on the restitution
        ax.plot(T, mode2, style, color="tab:red", lw=1.2, label="Mode II above, analytical")


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
    ap.add_argument("--out", default="collapse_diagram.png")
    ap.add_argument("--title", default=None)
    ap.add_argument("--dpi", type=int, default=150)
    args = ap.parse_args()

    doc = analytic(args)
    prop = doc["properties"]
    fig, ax = plt.subplots(figsize=(11, 5.4))
    c = prop["restitution"]
    draw_analytic(ax, doc, f"analytical (c = {c:.2f})", "-", True)
    if args.restitution is not None:
        draw_analytic(ax, analytic(args, args.restitution),
                      f"analytical (c = {args.restitution:.2f})", "--", False)
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


if __name__ == "__main__":
    main()
