#!/usr/bin/python3
"""Damage and collapse thresholds of a deck under one-sine pulses, by the DEM.

    scripts/dem_pulse_diagram.py --polydem build/polydem \
        --deck examples/spire/tip_pulse.toml --out docs/data/tip_dem_collapse.csv

For each pulse period T_p the deck is run (`polydem run --quiet --threads 1`,
into a temporary directory) with `ground_motion.period = T_p` and
`ground_motion.acceleration_g = a_p` on a coarse grid of a_p (--a_min to
--a_max, step --coarse), and every run is classified from its summary.json:
intact, damaged, Mode I or Mode II collapse. Each change of class between
neighbouring grid points is then bisected to --tol g; a bisection run of a
third class splits the interval, so every change the coarse grid brackets is
kept (collapse is not monotone in a_p: the lower Mode I loop can close again
before Mode II starts). Amplitudes are handled as integer multiples of --tol,
so a threshold is an amplitude that was run and the one --tol below it gave
the other class.

Output: a CSV, one row per T_p: the smallest a_p/g that is not intact
(a_p_damage_g), the smallest that collapses (a_p_collapse_g) and its mode, all
transitions as `a_g:from>to` separated by `;` (a_g is the first amplitude of
the new class), the number of runs and the wall seconds of the column; and a
JSON next to it (same name, .json) with every run (T_p, a_p, status, mode).
Columns go to --workers processes (concurrent.futures), each running its
deck one at a time; end_time is max(deck end_time, T_p + --after) so a Mode I
collapse after the pulse is seen.

Uses only the Python standard library.
"""

import argparse
import concurrent.futures as cf
import csv
import json
import os
import subprocess
import sys
import tempfile
import time

CLASSES = ("intact", "damaged", "I", "II")


def classify(summary):
    status = summary.get("status", "")
    if status == "collapsed":
        mode = summary.get("assessment", {}).get("collapse_mode", "")
        return mode if mode in ("I", "II") else "collapsed"
    if status in ("intact", "damaged"):
        return status
    raise RuntimeError(f"unexpected status {status!r}")


class Column:
    """The runs of one pulse period; amplitudes in units of tol."""

    def __init__(self, args, period):
        self.args = args
        self.period = period
        self.cache = {}
        self.runs = []

    def amplitude(self, k):
        return round(k * self.args.tol, 6)

    def run(self, k):
        if k in self.cache:
            return self.cache[k]
        a = self.amplitude(k)
        end_time = max(self.args.end_time, self.period + self.args.after)
        with tempfile.TemporaryDirectory(prefix="pulse_") as tmp:
            cmd = [self.args.polydem, "run", self.args.deck, "--quiet",
                   "--threads", "1", "--out", tmp,
                   "--set", f"ground_motion.acceleration_g={a}",
                   "--set", f"ground_motion.period={self.period}",
                   "--set", f"simulation.end_time={end_time}"]
            cmd += [x for s in self.args.set for x in ("--set", s)]
            proc = subprocess.run(cmd, stdout=subprocess.PIPE,
                                  stderr=subprocess.PIPE, text=True)
            path = os.path.join(tmp, "summary.json")
            if not os.path.exists(path):
                raise RuntimeError(f"{' '.join(cmd)} failed ({proc.returncode}): "
                                   f"{proc.stderr.strip()[-500:]}")
            with open(path) as f:
                summary = json.load(f)
        cls = classify(summary)
        self.cache[k] = cls
        self.runs.append({"T_p_s": self.period, "a_p_g": a, "class": cls,
                          "status": summary.get("status"),
                          "max_displacement_m":
                              summary.get("assessment", {}).get("max_displacement_m"),
                          "max_residual_displacement_m":
                              summary.get("assessment", {}).get("max_residual_displacement_m"),
                          "collapse_time_s":
                              summary.get("assessment", {}).get("collapse_time_s"),
                          "wall_seconds": summary.get("wall_seconds")})
        return cls

    def bisect(self, lo, hi, out):
        """Class changes between amplitudes lo < hi (in tol units)."""
        c_lo, c_hi = self.run(lo), self.run(hi)
        if c_lo == c_hi:
            return
        if hi - lo <= 1:
            out.append((hi, c_lo, c_hi))
            return
        mid = (lo + hi) // 2
        c_mid = self.run(mid)
        if c_mid != c_lo:
            self.bisect(lo, mid, out)
        if c_mid != c_hi:
            self.bisect(mid, hi, out)

    def scan(self):
        t0 = time.monotonic()
        step = max(1, round(self.args.coarse / self.args.tol))
        k0 = round(self.args.a_min / self.args.tol)
        k1 = round(self.args.a_max / self.args.tol)
        grid = list(range(k0, k1 + 1, step))
        if grid[-1] != k1:
            grid.append(k1)
        for k in grid:
            self.run(k)
        transitions = []
        for lo, hi in zip(grid, grid[1:]):
            self.bisect(lo, hi, transitions)
        transitions.sort()
        first = self.cache[grid[0]]
        damage = next((self.amplitude(k) for k, a, b in transitions
                       if a == "intact"), None)
        if first != "intact":
            damage = None  # below the scan: reported as "< a_min"
        collapse, mode = None, ""
        for k in sorted(self.cache):
            if self.cache[k] in ("I", "II", "collapsed"):
                collapse, mode = self.amplitude(k), self.cache[k]
                break
        return {"T_p_s": self.period,
                "first_class": first,
                "a_p_damage_g": damage,
                "a_p_collapse_g": collapse,
                "mode": mode,
                "transitions": [(self.amplitude(k), a, b) for k, a, b in transitions],
                "runs": len(self.runs),
                "wall_seconds": time.monotonic() - t0,
                "all_runs": sorted(self.runs, key=lambda r: r["a_p_g"])}


def column(args, period):
    return Column(args, period).scan()


def fmt(x):
    return "" if x is None else f"{x:.2f}"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--polydem", default="build/polydem", help="the binary")
    ap.add_argument("--deck", default="examples/spire/tip_pulse.toml")
    ap.add_argument("--periods", type=float, nargs="+",
                    default=[0.5, 0.6, 0.75, 0.9, 1.0, 1.25, 1.5, 1.75, 2.0],
                    help="pulse periods T_p [s]")
    ap.add_argument("--a_min", type=float, default=0.2, help="scan start [g]")
    ap.add_argument("--a_max", type=float, default=3.0, help="scan end [g]")
    ap.add_argument("--coarse", type=float, default=0.1, help="scan step [g]")
    ap.add_argument("--tol", type=float, default=0.01, help="bisection to [g]")
    ap.add_argument("--end_time", type=float, default=4.0,
                    help="run at least this long [s] (the deck's is replaced)")
    ap.add_argument("--after", type=float, default=3.0,
                    help="and at least this long after the pulse [s]")
    ap.add_argument("--set", action="append", default=[],
                    help="extra KEY=VALUE overrides for every run")
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--out", default="docs/data/tip_dem_collapse.csv")
    args = ap.parse_args()
    if not os.path.exists(args.polydem):
        sys.exit(f"{args.polydem}: no such binary (build it or pass --polydem)")

    t0 = time.monotonic()
    with cf.ProcessPoolExecutor(max_workers=args.workers) as pool:
        futures = [pool.submit(column, args, p) for p in args.periods]
        results = []
        for fut in futures:
            r = fut.result()
            results.append(r)
            print(f"T_p {r['T_p_s']:5.2f} s: damage {fmt(r['a_p_damage_g']):>5} g, "
                  f"collapse {fmt(r['a_p_collapse_g']):>5} g {r['mode']:2}, "
                  f"{r['runs']} runs, {r['wall_seconds']:.0f} s; "
                  + " ".join(f"{a:.2f}:{x}>{y}" for a, x, y in r["transitions"]),
                  flush=True)
    total = time.monotonic() - t0

    os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
    with open(args.out, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["T_p_s", "a_p_damage_g", "a_p_collapse_g", "mode",
                    "runs", "wall_seconds", "transitions"])
        for r in results:
            w.writerow([r["T_p_s"], fmt(r["a_p_damage_g"]), fmt(r["a_p_collapse_g"]),
                        r["mode"], r["runs"], f"{r['wall_seconds']:.1f}",
                        ";".join(f"{a:.2f}:{x}>{y}" for a, x, y in r["transitions"])])
    with open(os.path.splitext(args.out)[0] + ".json", "w") as f:
        json.dump({"deck": args.deck, "scan_g": [args.a_min, args.a_max, args.coarse],
                   "tolerance_g": args.tol, "overrides": args.set,
                   "total_wall_seconds": total, "columns": results}, f, indent=1)
    print(f"{sum(r['runs'] for r in results)} runs in {total:.0f} s -> {args.out}")


if __name__ == "__main__":
    main()
