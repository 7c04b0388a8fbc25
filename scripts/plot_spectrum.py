#!/usr/bin/python3
"""Response spectra of records or a suite, as `polydem analytic spectrum` writes them.

    scripts/plot_spectrum.py OUT/spectra.csv --marks OUT/marks.csv --out OUT/spectrum.png

`polydem analytic spectrum ... --out OUT` runs it itself. Two panels against
the period T (log scale): the pseudo-acceleration PSA in g and the
displacement Sd in mm. Each record is a thin grey line; a suite's median is
black and its median x exp(+-dispersion) (the 16th and 84th percentiles of a
lognormal) is shaded. The marks (the spire's and the tower's periods) are
vertical dashed lines with their names.

Uses only Debian's python3-numpy and python3-matplotlib.
"""

import argparse
import csv
import os

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_columns(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    header, body = rows[0], rows[1:]
    return header, body


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("spectra", help="spectra.csv of polydem analytic spectrum")
    p.add_argument("--marks", help="marks.csv: periods to mark (mark,period_s,...)")
    p.add_argument("--damping", type=float, default=None, help="damping ratio, for the title")
    p.add_argument("--title", default=None)
    p.add_argument("--out", default=None, help="PNG (default: spectrum.png beside the CSV)")
    p.add_argument("--dpi", type=int, default=130)
    a = p.parse_args()

    header, body = read_columns(a.spectra)
    data = np.array([[float(x) for x in row] for row in body])
    col = {name: i for i, name in enumerate(header)}
    T = data[:, 0]
    names = [h[: -len(".psa_g")] for h in header if h.endswith(".psa_g") and not h.startswith("median.")]

    fig, (ax_a, ax_d) = plt.subplots(1, 2, figsize=(11, 4.5))
    suite = "median.psa_g" in col
    for n in names:
        style = dict(color="0.6", lw=0.8) if suite else dict(lw=1.4)
        ax_a.plot(T, data[:, col[n + ".psa_g"]], label=None if suite else n, **style)
        ax_d.plot(T, 1000 * data[:, col[n + ".sd_m"]], label=None if suite else n, **style)
    if suite:
        beta = data[:, col["dispersion"]]
        for ax, key, k in ((ax_a, "median.psa_g", 1.0), (ax_d, "median.sd_m", 1000.0)):
            med = k * data[:, col[key]]
            ax.fill_between(T, med * np.exp(-beta), med * np.exp(beta), color="tab:blue", alpha=0.2,
                            label="median x exp(+-dispersion)")
            ax.plot(T, med, color="k", lw=2, label=f"median of {len(names)}")
    if a.marks and os.path.exists(a.marks):
        mh, mb = read_columns(a.marks)
        for row in mb:
            name, period = row[0], float(row[1])
            for ax in (ax_a, ax_d):
                ax.axvline(period, color="tab:red", ls="--", lw=1)
                ax.text(period, 0.98, f" {name} {period:.3g} s", color="tab:red", rotation=90, va="top",
                        ha="right", transform=ax.get_xaxis_transform(), fontsize=9)
    for ax, label in ((ax_a, "pseudo-acceleration PSA [g]"), (ax_d, "displacement Sd [mm]")):
        ax.set_xscale("log")
        ax.set_xlabel("period T [s]")
        ax.set_ylabel(label)
        ax.grid(True, which="both", alpha=0.3)
        ax.set_ylim(bottom=0)
    handles, labels = ax_a.get_legend_handles_labels()
    if labels:
        ax_a.legend(fontsize=8, loc="upper right" if suite else "best")
    title = a.title or os.path.basename(os.path.dirname(os.path.abspath(a.spectra)))
    if a.damping is not None:
        title += f", {100 * a.damping:g} % damping"
    fig.suptitle(title)
    fig.tight_layout()
    out = a.out or os.path.join(os.path.dirname(a.spectra), "spectrum.png")
    fig.savefig(out, dpi=a.dpi)


if __name__ == "__main__":
    main()
