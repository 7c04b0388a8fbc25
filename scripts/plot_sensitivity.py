#!/usr/bin/env python3
"""Tornado chart of the spire's collapse acceleration against the geometry
the paper does not give (issue 15, docs/analytical.md "Sensitivity").

Reads a CSV with columns parameter, baseline_value, low_value, low_lambda_g,
high_value, high_lambda_g, baseline_lambda_g (one row per parameter; the
lambdas from `polydem collapse ... --set spire.KEY=VALUE`) and draws one bar
per parameter from its low to its high variant's lambda, longest on top,
with the paper's 3DEC band shaded.

    scripts/plot_sensitivity.py docs/data/spire_lambda_sensitivity.csv \
        --out docs/img/spire_lambda_sensitivity.png
"""
import argparse
import csv

import matplotlib

matplotlib.use("Agg")
import matplotlib.patches  # noqa: E402
import matplotlib.pyplot as plt


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("csv")
    ap.add_argument("--out", required=True)
    ap.add_argument("--band", nargs=2, type=float, default=[0.164, 0.176], help="paper's 3DEC range, g")
    ap.add_argument("--dpi", type=int, default=110)
    a = ap.parse_args()
    rows = list(csv.DictReader(open(a.csv)))
    base = float(rows[0]["baseline_lambda_g"])
    rows.sort(key=lambda r: abs(float(r["high_lambda_g"]) - float(r["low_lambda_g"])))
    fig, ax = plt.subplots(figsize=(8, 0.45 * len(rows) + 1.4))
    ax.axvspan(a.band[0], a.band[1], color="0.85", label="paper, 3DEC (%.3f-%.3f g)" % tuple(a.band))
    for k, r in enumerate(rows):
        lo, hi = float(r["low_lambda_g"]), float(r["high_lambda_g"])
        # The low variant in the upper half of the row, the high one below it,
        # so that two variants on the same side of the defaults stay apart.
        for v, lam, c, dy in ((r["low_value"], lo, "tab:blue", 0.18), (r["high_value"], hi, "tab:red", -0.18)):
            ax.barh(k + dy, lam - base, left=base, color=c, alpha=0.75, height=0.34)
            ax.text(lam + (0.0008 if lam >= base else -0.0008), k + dy, v, va="center",
                    ha="left" if lam >= base else "right", fontsize=7)
    ax.axvline(base, color="k", lw=1, label="defaults: %.4f g" % base)
    for c, name in (("tab:blue", "first variant"), ("tab:red", "second variant")):
        ax.add_patch(matplotlib.patches.Rectangle((0, 0), 0, 0, color=c, alpha=0.75, label=name))
    ax.set_yticks(range(len(rows)))
    ax.set_yticklabels(["%s (%s)" % (r["parameter"], r["baseline_value"]) for r in rows], fontsize=8)
    ax.set_xlabel("collapse acceleration onto the window face (g)")
    ax.set_title("Spire: DEM collapse acceleration against the geometry the paper does not give", fontsize=9)
    ax.legend(fontsize=7, loc="lower right")
    lams = [float(r[c]) for r in rows for c in ("low_lambda_g", "high_lambda_g")]
    ax.set_xlim(min(lams + [a.band[0]]) - 0.012, max(lams) + 0.012)
    fig.tight_layout()
    fig.savefig(a.out, dpi=a.dpi)
    print("wrote", a.out)


if __name__ == "__main__":
    main()
