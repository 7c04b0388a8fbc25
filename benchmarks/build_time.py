#!/usr/bin/env python3
"""How long a fresh machine waits for the build, into
benchmarks/results/timings.csv (table `build`):

    /usr/bin/python3 benchmarks/build_time.py [--source DIR --commit C] [--repeat 1]

In a fresh build directory (no ccache, Release, as scripts/build.sh
configures it), `cmake --build DIR -j N --target polydem` (what
scripts/quickstart.sh builds), then, in another fresh directory, the whole
build (what scripts/test.sh builds). The configure step is not timed. The
figures are medians over REPEAT rounds, the two builds alternating. Run it
on a quiet machine (`uptime`)."""
import argparse
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(__file__))
import timings_csv  # noqa: E402


def timed_build(source, target):
    d = tempfile.mkdtemp(prefix="polydem_build_time_")
    try:
        subprocess.run(["cmake", "-S", source, "-B", d, "-DCMAKE_BUILD_TYPE=Release"], check=True,
                       stdout=subprocess.DEVNULL)
        cmd = ["cmake", "--build", d, "-j", str(os.cpu_count())] + (["--target", target] if target else [])
        load = timings_csv.load()
        t0 = time.monotonic()
        subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
        return time.monotonic() - t0, load
    finally:
        shutil.rmtree(d, ignore_errors=True)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--source", default=timings_csv.ROOT)
    ap.add_argument("--repeat", type=int, default=1)
    ap.add_argument("--commit", help="the commit --source holds (default: this clone's)")
    args = ap.parse_args()
    source = os.path.abspath(args.source)
    runs = {"polydem": [], "": []}
    loads = []
    for r in range(args.repeat):
        for target in ("polydem", ""):
            seconds, load = timed_build(source, target)
            runs[target].append(seconds)
            loads.append(load)
            print(f"round {r + 1}: {target or 'everything'}: {seconds:.0f} s (load {load:.1f})", file=sys.stderr)
    note = f"median of {args.repeat}; load average up to {max(loads):.1f} at a start; no ccache"
    n = os.cpu_count()
    rows = [
        {"table": "build", "command": f"cmake --build DIR -j {n} --target polydem",
         "quantity": "build for scripts/quickstart.sh (the polydem target)",
         "value": f"{statistics.median(runs['polydem']):.0f}", "unit": "s", "note": note},
        {"table": "build", "command": f"cmake --build DIR -j {n}",
         "quantity": "build for scripts/test.sh (everything)",
         "value": f"{statistics.median(runs['']):.0f}", "unit": "s", "note": note},
    ]
    timings_csv.record(rows, at_commit=args.commit)
    for r in rows:
        print(f"{r['quantity']}: {r['value']} {r['unit']}")


if __name__ == "__main__":
    main()
