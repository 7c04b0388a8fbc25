#!/usr/bin/python3
"""Writes examples/spire/synthetic_record.csv: a synthetic accelerogram that is
free to redistribute, for the earthquake example and the tests.

Method (documented so anyone can regenerate or vary it):
  1. Gaussian white noise, fixed seed 2008 (the Lincolnshire earthquake's year),
     sampled at dt = 0.01 s for 12 s;
  2. filtered by a Kanai-Tajimi soil filter (ground frequency 5 Hz, damping 0.6),
     the classic model of a firm-soil site, via the absolute acceleration of
     that oscillator;
  3. shaped by a Jennings-type envelope: rise t^2 over 1 s, strong motion to
     4 s, exponential decay (rate 0.5 /s) after it;
  4. baseline corrected (mean removed over the record) and scaled to a peak of
     0.05 g, the order of the 2008 event's recorded peaks at similar distance
     (paper 3.4 then scales it by 2-6).
Columns: time_s, acceleration_g.

Usage: scripts/make_synthetic_record.py [--seed N] [--pga G] [--out FILE]
"""
import argparse
import numpy as np


def kanai_tajimi(a, dt, f, zeta):
    """Absolute acceleration of an oscillator (f, zeta) on base acceleration a
    (Newmark average acceleration, 10 substeps per sample)."""
    w = 2 * np.pi * f
    u = v = 0.0
    acc = -a[0]
    out = np.zeros_like(a)
    sub = 10
    h = dt / sub
    keff = w * w + 2 * zeta * w * 2 / h + 4 / (h * h)
    for k in range(1, len(a)):
        for j in range(1, sub + 1):
            x = j / sub
            p = -((1 - x) * a[k - 1] + x * a[k])
            rhs = p + 4 / (h * h) * u + 4 / h * v + acc + 2 * zeta * w * (2 / h * u + v)
            u1 = rhs / keff
            v1 = 2 / h * (u1 - u) - v
            a1 = 4 / (h * h) * (u1 - u) - 4 / h * v - acc
            u, v, acc = u1, v1, a1
        out[k] = -2 * zeta * w * v - w * w * u
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--seed", type=int, default=2008)
    ap.add_argument("--pga", type=float, default=0.05, help="peak ground acceleration, g")
    ap.add_argument("--out", default="examples/spire/synthetic_record.csv")
    args = ap.parse_args()
    dt, duration = 0.01, 12.0
    t = np.arange(0.0, duration + dt / 2, dt)
    rng = np.random.default_rng(args.seed)
    noise = rng.standard_normal(t.size)
    a = kanai_tajimi(noise, dt, 5.0, 0.6)
    env = np.where(t < 1.0, t ** 2, np.where(t < 4.0, 1.0, np.exp(-0.5 * (t - 4.0))))
    a = a * env
    a -= a.mean()
    a *= args.pga / np.max(np.abs(a))
    a[0] = 0.0
    with open(args.out, "w") as f:
        f.write("time_s,acceleration_g\n")
        for ti, ai in zip(t, a):
            f.write(f"{ti:.2f},{ai:.6e}\n")
    print(f"wrote {args.out}: {t.size} samples, dt = {dt} s, PGA = {np.max(np.abs(a)):.4f} g")


if __name__ == "__main__":
    main()
