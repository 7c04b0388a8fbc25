#!/usr/bin/python3
"""The paper's Figures 5 and 7(b) from polydem sweep results, with the
analytical rocking curves drawn over the DEM curves.

    scripts/plot_pulse_figures.py --spire out/sweep_spire --tip out/sweep_tip \
        --polydem build/polydem --out docs/img/pulse_figures.png

--spire and --tip are one or more output directories of `polydem sweep ... --vary
ground_motion.period=... --search ground_motion.acceleration_g=...` (their
boundaries.csv). Two panels, as the paper's figures:

  (a) Figure 5: damage and collapse of the whole spire (DEM, 402 blocks) and
      of its solid tip alone (DEM), with the analytical rocking collapse
      curves of the whole spire (conical shell) and of the tip (solid cone):
      minimum overturning amplitude (lower edge of the Mode I loop) and the
      Mode II boundary above which the body overturns without impact.
  (b) Figure 7(b): the spire cracked below its solid tip and rocking above
      the crack, cracked height --H_bar (the paper's worst, 4.1 m), against
      the whole spire's DEM curves.

DEM curves: for each T_p the lowest a_p that damages (residual displacement
over the deck's damage_displacement) and the lowest that collapses (circle
Mode I, square Mode II), the start of Mode II above a Mode I loop (diamond)
and the top of a Mode I loop that closes before Mode II (x). Analytical
curves come from `polydem analytic collapse-diagram --json`.

Uses Debian's python3-numpy and python3-matplotlib.
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

PERIOD = "ground_motion.period"
AMPLITUDE = "ground_motion.acceleration_g"


def read_boundaries(directory):
    """Rows of DIR/boundaries.csv: T_p, damage, collapse, mode, transitions."""
    rows = []
    with open(os.path.join(directory, "boundaries.csv")) as f:
        for r in csv.DictReader(f):
            def num(key):
                v = r.get(key, "")
                return float(v) if v else np.nan
            trans = []
            for item in filter(None, r["transitions"].split(";")):
                a, change = item.split(":")
                below, above = change.split(">")
                trans.append((float(a), below, above))
            rows.append({"T": float(r[PERIOD]), "damage": num("damage_" + AMPLITUDE),
                         "collapse": num("collapse_" + AMPLITUDE), "mode": r["collapse_mode"],
                         "stones": num("stones_lost_" + AMPLITUDE),  # NaN in tables without the column
                         "transitions": trans, "runs": int(r["runs"])})
    rows.sort(key=lambda r: r["T"])
    return rows


def analytic(polydem, body_args, Tp_min, Tp_max, a_max):
    cmd = [polydem, "analytic", "collapse-diagram", *body_args, "--Tp_min", str(Tp_min),
           "--Tp_max", str(Tp_max), "--Tp_count", "60", "--a_max", str(a_max), "--points", "100", "--json"]
    doc = json.loads(subprocess.run(cmd, check=True, stdout=subprocess.PIPE, text=True).stdout)
    T = np.array([c["T_p_s"] for c in doc["columns"]])
    low = np.array([c["min_collapse_g"] if c["min_collapse_g"] is not None else np.nan
                    for c in doc["columns"]], float)
    mode2 = np.array([c.get("mode2_boundary_g") if c.get("mode2_boundary_g") is not None else np.nan
                      for c in doc["columns"]], float)
    return T, low, mode2, doc["properties"]


def draw_analytic(ax, curve, label, color, style):
    T, low, mode2, props = curve
    ax.plot(T, low, style, color=color, lw=1.6,
            label=f"{label}: minimum overturning (analytical, p = {props['p_rad_s']:.2f} rad/s)")
    ax.plot(T, mode2, style, color=color, lw=0.9, alpha=0.8, label=f"{label}: Mode II above (analytical)")


def draw_dem(ax, rows, label, color, ymax):
    T = [r["T"] for r in rows]
    ax.plot(T, [r["damage"] for r in rows], "v--", color=color, ms=5, lw=0.8, mfc="none",
            label=f"{label}: damage from (DEM)")
    stones = [r["stones"] for r in rows]
    if np.isfinite(stones).any():
        ax.plot(T, stones, "^:", color=color, ms=5, lw=0.8,
                label=f"{label}: first stones lost from (DEM)")
    ax.plot(T, [r["collapse"] for r in rows], "-", color=color, lw=1.2)
    for mode, marker in (("I", "o"), ("II", "s")):
        sel = [r for r in rows if r["mode"] == mode and not np.isnan(r["collapse"])]
        if sel:
            ax.plot([r["T"] for r in sel], [r["collapse"] for r in sel], marker, color=color, ms=6,
                    label=f"{label}: collapse from, Mode {mode} (DEM)")
    m2 = [(r["T"], a) for r in rows for a, lo, hi in r["transitions"]
          if hi == "II" and lo != "II" and a > r["collapse"]]
    if m2:
        ax.plot(*zip(*m2), "D:", color=color, ms=5, mfc="none", lw=0.8, label=f"{label}: Mode II from (DEM)")
    tops = [(r["T"], a) for r in rows for a, lo, hi in r["transitions"] if lo == "I" and hi in ("intact", "damaged")]
    if tops:
        ax.plot(*zip(*tops), "x", color=color, ms=6, label=f"{label}: top of a Mode I loop (DEM)")
    none = [r["T"] for r in rows if np.isnan(r["collapse"])]
    if none:
        ax.plot(none, [0.97 * ymax] * len(none), "^", color=color, mfc="none", ms=6,
                label=f"{label}: no collapse in the scan (DEM)")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--spire", required=True, nargs="+",
                    help="polydem sweep output(s) of examples/spire/pulse.toml (rows are merged)")
    ap.add_argument("--tip", required=True, nargs="+", help="polydem sweep output(s) of examples/spire/tip_pulse.toml")
    ap.add_argument("--polydem", default="build/polydem")
    ap.add_argument("--H_bar", type=float, default=4.1, help="cracked height of panel (b), m")
    ap.add_argument("--Tp_min", type=float, default=0.3)
    ap.add_argument("--Tp_max", type=float, default=2.2)
    ap.add_argument("--y_max", type=float, default=3.2, help="top of the a_p axis, g")
    ap.add_argument("--out", default="pulse_figures.png")
    ap.add_argument("--dpi", type=int, default=90)
    args = ap.parse_args()

    spire = sorted((r for d in args.spire for r in read_boundaries(d)), key=lambda r: r["T"])
    tip = sorted((r for d in args.tip for r in read_boundaries(d)), key=lambda r: r["T"])
    a_max = args.y_max * 1.6
    shell = analytic(args.polydem, ["--body", "shell", "--r_b", "1.064", "--H", "9.4"],
                     args.Tp_min, args.Tp_max, a_max)
    cone = analytic(args.polydem, ["--body", "cone", "--r_b", "0.4301", "--H", "3.4"],
                    args.Tp_min, args.Tp_max, a_max)
    cracked = analytic(args.polydem, ["--body", "cracked", "--H_bar", str(args.H_bar)],
                       args.Tp_min, args.Tp_max, a_max)

    fig, axes = plt.subplots(1, 2, figsize=(15, 6.5), sharey=True)
    ax = axes[0]
    draw_analytic(ax, shell, "whole spire 9.4 m", "tab:blue", "-")
    draw_analytic(ax, cone, "tip 3.4 m", "tab:red", "-")
    draw_dem(ax, spire, "whole spire", "navy", args.y_max)
    draw_dem(ax, tip, "tip alone", "darkred", args.y_max)
    ax.set_title("(a) as the paper's Figure 5: damage and collapse under a one-sine pulse")
    ax = axes[1]
    draw_analytic(ax, cracked, f"cracked spire, H\u0304 = {args.H_bar:g} m", "tab:green", "-")
    draw_analytic(ax, shell, "whole spire 9.4 m", "tab:blue", "--")
    draw_dem(ax, spire, "whole spire", "navy", args.y_max)
    ax.set_title(f"(b) as the paper's Figure 7(b): rocking above a crack at H\u0304 = {args.H_bar:g} m")
    for ax in axes:
        ax.set_xlim(args.Tp_min, args.Tp_max)
        ax.set_ylim(0, args.y_max)
        ax.set_xlabel("pulse period T_p [s]")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=6.5, loc="upper right")
    axes[0].set_ylabel("pulse amplitude a_p [g]")
    fig.tight_layout()
    fig.savefig(args.out, dpi=args.dpi)
    print(f"wrote {args.out}")
    for name, rows in (("whole spire", spire), ("tip alone", tip)):
        print(f"{name}: {sum(r['runs'] for r in rows)} DEM runs over {len(rows)} periods")


if __name__ == "__main__":
    main()
