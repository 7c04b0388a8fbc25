#!/usr/bin/python3
"""Plot the energy ledger of a polydem run and its numerical line.

    scripts/plot_energy.py out/main/results.h5 --out energy.png

Reads /energies of results.h5 (docs/results.md): kinetic, gravitational
(relative to the start), strain (elastic energy in the joints), slip and
damping (dissipated, cumulative), load work (work of the ground motion and
loads, cumulative) and numerical: the drift of kinetic + gravitational +
strain + slip + damping - load work from its first value, the energy the
numerics made (> 0) or lost (< 0).

Top panel: every term in J. Bottom panel: the numerical line over the energy
put in so far (what the blocks had at the start, the net work of the loads
and the potential gravity released, each when positive), in %; its largest
magnitude is the `energy_balance_error` of summary.json.

Uses only Debian's python3-numpy, python3-matplotlib and python3-h5py.
"""

import argparse
import os

import h5py
import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

TERMS = [  # dataset, label, style
    ("kinetic", "kinetic", dict(color="tab:blue")),
    ("gravitational", "gravitational", dict(color="tab:brown")),
    ("strain", "strain", dict(color="tab:green")),
    ("slip", "slip (dissipated)", dict(color="tab:orange")),
    ("damping", "damping (dissipated)", dict(color="tab:purple")),
    ("load_work", "load work", dict(color="tab:red")),
    ("numerical", "numerical", dict(color="black", lw=1.8, ls="--")),
]


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("results", help="results.h5 written by polydem run")
    ap.add_argument("--out", help="PNG to write (default: energy.png beside results.h5)")
    ap.add_argument("--title", help="figure title (default: the deck path stored in the file)")
    ap.add_argument("--dpi", type=int, default=110)
    args = ap.parse_args(argv)

    with h5py.File(args.results, "r") as f:
        if "energies" not in f or "time" not in f["energies"]:
            raise SystemExit(f"{args.results}: no /energies (the deck set output.energies = false)")
        e = f["energies"]
        time = e["time"][:]
        terms = {name: e[name][:] for name, _, _ in TERMS if name in e}
        deck = f["deck"].attrs.get("path", "") if "deck" in f else ""
        deck = deck.decode() if isinstance(deck, bytes) else str(deck)
    if "numerical" not in terms:
        raise SystemExit(f"{args.results}: no /energies/numerical")

    zero = np.zeros_like(time)
    kinetic, strain = terms.get("kinetic", zero), terms.get("strain", zero)
    gravitational, load_work = terms.get("gravitational", zero), terms.get("load_work", zero)
    put_in = (kinetic[0] + strain[0] + np.maximum(0.0, load_work - load_work[0])
              + np.maximum(0.0, gravitational[0] - gravitational))
    reference = np.maximum.accumulate(put_in)
    drift = np.abs(terms["numerical"])
    error = np.where(reference > 0, drift / np.where(reference > 0, reference, 1.0), 0.0)
    worst = float(np.max(np.maximum.accumulate(drift)) / reference[-1]) if reference[-1] > 0 else 0.0

    fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(7.5, 6.0),
                                      gridspec_kw=dict(height_ratios=[2.3, 1.0]))
    for name, label, style in TERMS:
        if name in terms:
            top.plot(time, terms[name], label=label, lw=style.pop("lw", 1.2), **style)
    top.axhline(0.0, color="0.5", lw=0.5)
    top.set_ylabel("energy [J]")
    top.grid(True, lw=0.4, alpha=0.5)
    top.legend(fontsize=8, ncol=2, loc="best")

    bottom.plot(time, 100.0 * error, color="black", lw=1.1)
    bottom.set_ylabel("numerical / put in [%]")
    bottom.set_xlabel("time [s]")
    bottom.grid(True, lw=0.4, alpha=0.5)
    bottom.set_xlim(float(time[0]), float(time[-1]))
    bottom.text(0.01, 0.92, f"largest |numerical| / energy put in = {100.0 * worst:.3g} %",
                transform=bottom.transAxes, va="top", fontsize=8,
                bbox=dict(facecolor="white", edgecolor="0.8", alpha=0.9))

    fig.suptitle(args.title if args.title is not None else f"energy ledger: {deck or args.results}", fontsize=11)
    fig.tight_layout()
    out = args.out or os.path.join(os.path.dirname(os.path.abspath(args.results)), "energy.png")
    fig.savefig(out, dpi=args.dpi)
    plt.close(fig)
    print(f"wrote {out} (numerical {worst:.3e} of the energy put in)")


if __name__ == "__main__":
    main()
