"""polydem against YADE on the same running-bond wall, side by side in one run
(issue 12, "Against a peer"). Started by benchmarks/yade_side_by_side.sh.

For each wall size and thread count it runs, each in its own process under
/usr/bin/time -v (for the peak resident memory):
  - benchmarks/polydem_wall.py (polydem's Python module, PYTHONPATH=BUILD/python)
  - benchmarks/yade_wall.py    (yade -n -x -j THREADS), only when `yade` is on PATH
Each process builds the wall, settles it under gravity, times a fixed
simulated interval from the settled state and prints "RESULT {json}"; this
script collects them into one markdown table (and a CSV with --csv).

The wall (both codes): bricks L x W x H = 0.3 x 0.3 x 0.15 m (length along
the wall, width through it, height: the issue's "0.3 x 0.3 x 0.15 m" read as
length x width x height, so a 10-course wall is 1.5 m high and 0.3 m thick),
one leaf, running (stretcher) bond with half bricks at both ends of the odd
courses, on a fixed base slab; kn = 1e10 Pa/m, ks = 0.4 kn, phi = 30 deg,
density 2600 kg/m^3. A size "CxB" is C courses of B whole bricks (B - 1 whole
and two halves in the odd courses): 10x10 = 105 bricks, 20x20 = 410,
40x25 = 1020.

Stiffness mapping: YADE's Polyhedra law gives Fn = kn_Y x (overlap volume);
a flat joint of area A closed by d overlaps A d, so kn_Y equals polydem's kn
per unit area (young = 2 kn for two equal materials). YADE's shear stiffness
is per contact (N/m): poisson is chosen so that ks_Y = ks x A for a whole
brick's bed (A = L W = 0.09 m^2), the brick on the slab. Details in
yade_wall.py's header and docs/benchmarks.md ("Against YADE").

Measures, per code, size and thread count: steps and simulated interval
timed, contacts (block pairs pressed together at the settled state: polydem's
pairs with a compressed subcontact, YADE's real interactions, i.e. with an
overlap volume), wall time of the timed interval (stepping only, measured
inside the process), wall time per simulated second, per step and per
contact-step = wall / (steps x contacts), and the process's peak RSS (which
includes building and settling the wall and the interpreter: python3 with
numpy for polydem, YADE's own Python for YADE; the baseline of each
interpreter alone is printed under the table).
"""
import argparse
import csv
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
TIME = "/usr/bin/time"


def peak_rss_mib(stderr_text):
    m = re.search(r"Maximum resident set size \(kbytes\): (\d+)", stderr_text)
    return int(m.group(1)) / 1024.0 if m else None


def measured(cmd, env):
    """Run cmd under /usr/bin/time -v; return (RESULT dict, peak RSS MiB)."""
    full = ([TIME, "-v"] if os.access(TIME, os.X_OK) else []) + cmd
    p = subprocess.run(full, env=env, capture_output=True, text=True)
    lines = [l for l in p.stdout.splitlines() if l.startswith("RESULT ")]
    if p.returncode != 0 or not lines:
        sys.stderr.write(p.stdout[-3000:] + p.stderr[-3000:])
        raise SystemExit("failed: " + " ".join(cmd))
    return json.loads(lines[-1][len("RESULT "):]), peak_rss_mib(p.stderr)


def baseline(cmd, env):
    if not os.access(TIME, os.X_OK):
        return None
    p = subprocess.run([TIME, "-v"] + cmd, env=env, capture_output=True, text=True)
    return peak_rss_mib(p.stderr)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build", default="build", help="polydem build directory (its python/ is used)")
    ap.add_argument("--sizes", default="10x10,20x20,40x25", help="COURSESxBRICKS,...")
    ap.add_argument("--threads", default="1,2")
    ap.add_argument("--polydem-interval", type=float, help="timed simulated s for polydem (default 1)")
    ap.add_argument("--yade-interval", type=float, help="timed simulated s for YADE (default 0.01)")
    ap.add_argument("--settle-max", type=float, help="longest settle (simulated s), both codes (default 0.5)")
    ap.add_argument("--yade-dt", type=float, default=0.0,
                    help="YADE's time step (s); default 0: 0.8 x YADE's polyhedra P-wave estimate")
    ap.add_argument("--settle-speed", type=float, default=1e-3, help="settled when every brick is slower (m/s)")
    ap.add_argument("--quick", action="store_true",
                    help="a check that everything runs: defaults become intervals 0.05 s (polydem) and "
                         "0.002 s (YADE), settle at most 0.03 s")
    ap.add_argument("--polydem-fixed-threads", action="store_true",
                    help="polydem with simulation.adaptive_threads = false (default: the thread governor on)")
    ap.add_argument("--polydem-history-interval", type=float, default=0.01,
                    help="polydem's output.history_interval (s), as in its example decks; 0: every step "
                         "(histories and energy ledger; YADE's half records nothing)")
    ap.add_argument("--no-yade", action="store_true", help="run only the polydem half")
    ap.add_argument("--csv", help="also write the table as CSV here")
    a = ap.parse_args()
    defaults = (0.05, 0.002, 0.03) if a.quick else (1.0, 0.01, 0.5)
    a.polydem_interval, a.yade_interval, a.settle_max = (
        d if v is None else v for v, d in zip((a.polydem_interval, a.yade_interval, a.settle_max), defaults))

    if not os.path.isdir(os.path.join(a.build, "python", "polydem")):
        raise SystemExit(f"no polydem Python module in {a.build}/python: build polydem (scripts/build.sh) "
                         "or give --build DIR")
    env = dict(os.environ)
    env["PYTHONPATH"] = os.path.join(os.path.abspath(a.build), "python") + (
        os.pathsep + env["PYTHONPATH"] if env.get("PYTHONPATH") else "")
    env.pop("OMP_NUM_THREADS", None)  # each run is given its thread count explicitly
    yade = None if a.no_yade else shutil.which("yade")
    sizes = [tuple(int(x) for x in s.lower().split("x")) for s in a.sizes.split(",")]
    threads = [int(t) for t in a.threads.split(",")]

    print("# polydem against YADE, running-bond wall of 0.3 x 0.3 x 0.15 m bricks (L x W x H), one leaf,")
    print("# kn = 1e10 Pa/m, ks = 0.4 kn, phi = 30 deg; settled under gravity, then a fixed interval timed")
    cpu = "?"
    try:
        with open("/proc/cpuinfo") as f:
            cpu = next(l.split(":", 1)[1].strip() for l in f if l.startswith("model name"))
    except (OSError, StopIteration):
        pass
    with open("/proc/loadavg") as f:
        load = " ".join(f.read().split()[:3])
    print(f"# {os.cpu_count()} cores, {cpu}, load at start {load}")
    if yade is None:
        why = "--no-yade given" if a.no_yade else "yade is not installed: no `yade` on PATH; Debian: apt-get install yade"
        print(f"# YADE: NOT RUN ({why}); only the polydem half runs.")
    else:
        v = subprocess.run([yade, "--version"], capture_output=True, text=True).stdout.strip().splitlines()
        print(f"# YADE: {v[-1] if v else yade}")
    print(f"# intervals: polydem {a.polydem_interval} s, YADE {a.yade_interval} s; settle <= {a.settle_max} s "
          f"until every brick < {a.settle_speed} m/s")
    print(f"# polydem records its histories and energy ledger "
          + (f"every {a.polydem_history_interval} s" if a.polydem_history_interval > 0 else "every step")
          + "; YADE's half records nothing while timed")
    print()

    py = "/usr/bin/python3"
    common = ["--settle-max", str(a.settle_max), "--settle-speed", str(a.settle_speed)]
    rows = []
    states = tempfile.TemporaryDirectory(prefix="yade_side_by_side_")  # YADE's settled walls
    for courses, bricks in sizes:
        for t in threads:
            jobs = [("polydem", [py, os.path.join(HERE, "polydem_wall.py"), "--threads", str(t),
                                 "--interval", str(a.polydem_interval),
                                 "--history-interval", str(a.polydem_history_interval)]
                     + (["--fixed-threads"] if a.polydem_fixed_threads else []))]
            if yade:
                jobs.append(("yade", [yade, "-n", "-x", "-j", str(t), os.path.join(HERE, "yade_wall.py"),
                                      "--interval", str(a.yade_interval), "--dt", str(a.yade_dt),
                                      "--state", os.path.join(states.name, f"wall_{courses}x{bricks}.yade.gz")]))
            for code, cmd in jobs:
                cmd = cmd + ["--courses", str(courses), "--bricks", str(bricks)] + common
                r, rss = measured(cmd, env)
                contacts = r.get("contacts_loaded", r["contacts"])
                rows.append({
                    "size": f"{courses}x{bricks}", "code": code, "threads": t, "blocks": r["blocks"],
                    "dt_s": r["dt"], "settled_at_s": r["settle_time"], "settled_speed_m_s": r["settled_speed"],
                    "interval_s": r["interval"], "steps": r["steps"], "contacts": contacts,
                    "subcontacts": r.get("subcontacts"), "wall_s": r["wall"],
                    "settle_reused": r.get("settled_state_reused", False),
                    "threads_profile": r.get("threads_profile"),
                    "wall_per_sim_s": r["wall"] / r["interval"], "wall_per_step_s": r["wall"] / r["steps"],
                    "ns_per_contact_step": 1e9 * r["wall"] / (r["steps"] * contacts), "peak_rss_mib": rss,
                })
                sys.stdout.flush()

    # Ratio YADE / polydem per contact-step, same size and threads.
    by = {(r["size"], r["code"], r["threads"]): r for r in rows}
    for r in rows:
        p = by.get((r["size"], "polydem", r["threads"]))
        y = by.get((r["size"], "yade", r["threads"]))
        r["yade_over_polydem_per_contact_step"] = (
            y["ns_per_contact_step"] / p["ns_per_contact_step"] if p and y else None)

    def fmt(v, f="{:.3g}"):
        return "-" if v is None else (f.format(v) if isinstance(v, float) else str(v))

    head = ["size", "code", "threads", "blocks", "dt (s)", "steps", "contacts", "subcontacts", "wall (s)",
            "wall / simulated s", "wall / step (s)", "ns / contact-step", "YADE / polydem", "peak RSS (MiB)"]
    keys = ["size", "code", "threads", "blocks", "dt_s", "steps", "contacts", "subcontacts", "wall_s",
            "wall_per_sim_s", "wall_per_step_s", "ns_per_contact_step", "yade_over_polydem_per_contact_step",
            "peak_rss_mib"]
    print("| " + " | ".join(head) + " |")
    print("|" + "---|" * len(head))
    for r in rows:
        print("| " + " | ".join(fmt(r[k]) for k in keys) + " |")
    print()
    for r in rows:
        note = "" if r["settled_speed_m_s"] < a.settle_speed else " -- NOT settled: --settle-max reached"
        if r["settle_reused"]:
            note += " (the wall YADE settled for the first thread count, loaded)"
        tp = r["threads_profile"]
        if r["code"] == "polydem" and r["threads"] > 1 and tp:
            note += (f"; thread governor: {tp.get('probes')} probes, {tp.get('switches')} switches, "
                     f"{tp.get('steps_on_one')} steps on one thread (whole run)")
        print(f"# {r['size']} {r['code']} {r['threads']} thread(s): settle ended at {r['settled_at_s']:.4f} s "
              f"(fastest brick {r['settled_speed_m_s']:.2g} m/s){note}, timed {r['interval_s']:.4g} s")
    b = baseline([py, "-c", "import numpy, polydem"], env)
    print(f"# interpreter alone (peak RSS): python3 + numpy + polydem {fmt(b)} MiB", end="")
    if yade:
        print(f", yade {fmt(baseline([yade, '-n', '-x', os.devnull], env))} MiB")
    else:
        print()
    if a.csv:
        with open(a.csv, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
            w.writeheader()
            w.writerows(rows)


if __name__ == "__main__":
    main()
