#!/usr/bin/env python3
"""The energy ledger's numerical line on the runs an engineer relies on, into
benchmarks/results/ledger.csv (table `ledger`, docs/results.md):

    /usr/bin/python3 benchmarks/ledger.py build/polydem [--case C]... [--jobs 2]
        [--force] [--out DIR] [--set KEY=VALUE]...

  cases  every deck of examples/verification/ (its own end time);
         main      `polydem run --default`, the 0.1 g/s ramp through the collapse;
         pulse35, pulse50, pulse100
                   `examples/spire/pulse.toml` at 0.35, 0.5 and 1.0 g, T_p = 1 s,
                   on the 60 m platform, run through the collapse
                   (stop_on_collapse = false) until the stones are at rest
                   or the deck's 12 s;
         earthquake  `examples/spire/earthquake.toml` (the record x4, 14 s).

Each run is `nice -n 10 polydem run ... --threads 1`, at most --jobs at a
time. Per run: the energy put in, the numerical line at the end (J, of the
energy put in, of the slip and damping dissipated where they are more than
a millionth of the energy put in) and the part of it the
detections account for (summary.json's numerical_at_detections_J), the
largest |numerical| over the energy put in during the run, the slip and
damping, the status and the wall time. `--set` adds an override to every run (a setting under test,
e.g. simulation.joint_model="overlap"); it is recorded in the `setting`
column. A (case, setting) already in the CSV is skipped unless --force."""
import argparse
import concurrent.futures
import csv
import datetime
import glob
import json
import os
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(__file__))
import convergence  # noqa: E402
import timings_csv  # noqa: E402

ROOT = timings_csv.ROOT
PATH = os.path.join(ROOT, "benchmarks", "results", "ledger.csv")
COLUMNS = ["machine", "cpu", "commit", "date", "case", "setting", "quantity", "value", "unit"]


def cases():
    """case name -> the `polydem run` arguments; the order is the table's."""
    out = {}
    for deck in sorted(glob.glob(os.path.join(ROOT, "examples", "verification", "*.toml"))):
        out[os.path.basename(deck)[:-5]] = [os.path.relpath(deck, ROOT)]
    out["main"] = ["--default"]
    for name, a in (("pulse35", 0.35), ("pulse50", 0.5), ("pulse100", 1.0)):
        out[name] = ["examples/spire/pulse.toml", "--set", f"ground_motion.acceleration_g={a}",
                     "--set", "ground_motion.period=1.0", "--set", "assessment.stop_on_collapse=false"]
    out["earthquake"] = ["examples/spire/earthquake.toml"]
    return out


def quantities(s):
    e = s["energy"]
    put_in = e["put_in_J"]
    return [("status", s["status"], ""),
            ("simulated time", f'{s["end_time_s"]:.3f}', "s"),
            ("energy put in", f"{put_in:.4g}", "J"),
            ("slip", f'{e["slip_dissipation_J"]:.4g}', "J"),
            ("damping", f'{e["damping_dissipation_J"]:.4g}', "J"),
            ("numerical", f'{e["numerical_J"]:.3g}', "J"),
            ("numerical of the energy put in", f'{100 * e["numerical_J"] / put_in:.3g}' if put_in > 0 else "-", "%"),
            ("numerical of slip and damping",
             f'{100 * e["numerical_of_dissipation"]:.3g}'
             if e["slip_dissipation_J"] + e["damping_dissipation_J"] > 1e-6 * put_in else "-", "%"),
            ("largest numerical excursion of the energy put in", f'{100 * s["energy_balance_error"]:.3g}', "%"),
            ("numerical at detections", f'{e["numerical_at_detections_J"]:.3g}', "J")]


def run_one(polydem, case, args, overrides, out):
    d = os.path.join(out, case)
    cmd = ["nice", "-n", "10", polydem, "run", *args, "--threads", "1", "--quiet", "--out", d]
    for o in overrides:
        cmd += ["--set", o]
    path = os.path.join(d, "summary.json")
    if os.path.exists(path):
        os.remove(path)  # a run that fails must not leave an earlier one's summary to be read
    start = time.monotonic()
    p = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True)
    wall = time.monotonic() - start
    if not os.path.exists(path):
        raise RuntimeError(f"{' '.join(cmd)}: exit {p.returncode}\n{p.stderr[-2000:]}")
    with open(path, encoding="utf-8") as f:
        return quantities(json.load(f)) + [("wall time, 1 thread", f"{wall:.1f}", "s")]


def read_rows():
    if not os.path.exists(PATH):
        return []
    with open(PATH, newline="", encoding="utf-8") as f:
        return list(csv.DictReader(f))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("polydem")
    ap.add_argument("--case", action="append", help="only these cases (repeatable)")
    ap.add_argument("--set", action="append", default=[], dest="overrides", help="an override for every run")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--force", action="store_true")
    ap.add_argument("--out", default="/tmp/polydem_ledger")
    a = ap.parse_args()
    polydem = os.path.abspath(a.polydem)
    setting = ", ".join(a.overrides) or "default"
    all_cases = cases()
    chosen = [c for c in all_cases if not a.case or c in a.case]
    rows = read_rows()
    done = {(r["case"], r["setting"]) for r in rows}
    todo = [c for c in chosen if a.force or (c, setting) not in done]
    machine, cpu = timings_csv.machine(), timings_csv.cpu()
    commit, date = convergence.solver_commit(), datetime.date.today().isoformat()
    out = os.path.join(a.out, setting.replace(" ", "_").replace('"', "").replace("=", "-").replace(",", ""))
    with concurrent.futures.ThreadPoolExecutor(max_workers=a.jobs) as pool:
        futures = {pool.submit(run_one, polydem, c, all_cases[c], a.overrides, out): c for c in todo}
        for fut in concurrent.futures.as_completed(futures):
            case = futures[fut]
            try:
                got = fut.result()
            except RuntimeError as e:  # a deck the setting refuses (cohesion under the overlap model)
                print(f"ledger: {case} ({setting}) not run: {str(e).splitlines()[-1]}", file=sys.stderr)
                continue
            # Re-read: another ledger.py (another setting) may have written since.
            rows = [r for r in read_rows() if (r["case"], r["setting"]) != (case, setting)]
            rows += [dict(zip(COLUMNS, [machine, cpu, commit, date, case, setting, q, v, u])) for q, v, u in got]
            order = list(all_cases)
            rows.sort(key=lambda r: (r["setting"] != "default", r["setting"],
                                     order.index(r["case"]) if r["case"] in order else len(order)))
            with open(PATH, "w", newline="", encoding="utf-8") as f:
                w = csv.DictWriter(f, COLUMNS)
                w.writeheader()
                w.writerows(rows)
            print(f"ledger: {case} ({setting}) done", file=sys.stderr)


if __name__ == "__main__":
    main()
