#!/usr/bin/env python3
"""The spire's speed as users meet it, into benchmarks/results/timings.csv
(table `spire_speed`, shown in docs/benchmarks.md and the README):

    /usr/bin/python3 benchmarks/spire_speed.py [--build build] [--repeat 3]

  - the main job, `polydem run --default` (the quickstart's run), on every
    core: its wall time and microseconds per step;
  - the earthquake deck for 0.3 s of motion (`examples/spire/earthquake.toml
    --set simulation.end_time=0.3 --set output.snapshot_interval=0`) on 1 and
    2 threads, with each damping scheme and (--overlap) under the overlap
    joint model, (--points-follow) with the joint points following the
    blocks (`simulation.joint_sampling = "step"`), (--detection) with the
    joints re-sampled at detection instead of clipped as they move
    (`simulation.joint_sampling = "detection"`, the main job too) and
    clipped at every step (the travel 1e-12 m), and (--scene-trigger)
    with the joints re-sampled scene-wide instead of pair by pair, the main
    job too: microseconds per step and subcontact updates per second.
The cases alternate, REPEAT rounds; each figure is the median over the
rounds. Run it on a quiet machine (`uptime`): the note column keeps the
highest load average seen at the start of a run."""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(__file__))
import timings_csv  # noqa: E402

EQ = ["examples/spire/earthquake.toml", "--set", "simulation.end_time=0.3", "--set", "output.snapshot_interval=0"]


def on(threads):
    """'1 thread', '2 threads': the end of a case's name."""
    return f"{threads} thread{'s' if threads > 1 else ''}"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", default="build")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--no-main-job", action="store_true", help="only the earthquake deck")
    ap.add_argument("--overlap", action="store_true", help="also the earthquake deck under the overlap joint model")
    ap.add_argument("--points-follow", action="store_true",
                    help="also the earthquake deck with the joint points following the blocks")
    ap.add_argument("--detection", action="store_true",
                    help="also the main job and the earthquake deck with the joints re-sampled at detection, "
                         "and the earthquake deck with them clipped at every step")
    ap.add_argument("--scene-trigger", action="store_true",
                    help="also the main job and the earthquake deck with the joints re-sampled scene-wide")
    ap.add_argument("--only", action="append", default=[],
                    help="only the cases whose name contains this (repeatable)")
    args = ap.parse_args()
    polydem = os.path.abspath(os.path.join(args.build, "polydem"))
    cases = [] if args.no_main_job else [("main job", ["--default"], None)]
    def earthquake(label, overrides):
        """The earthquake deck under `overrides`, on 1 and 2 threads."""
        for threads in (1, 2):
            cases.append((f"earthquake 0.3 s, {label}, {on(threads)}", EQ + overrides, threads))

    for scheme in ("explicit", "split"):
        earthquake(scheme, ["--set", f'simulation.damping_scheme="{scheme}"'])
    if args.overlap:
        earthquake("overlap model", ["--set", 'simulation.joint_model="overlap"'])
    if args.points_follow:
        earthquake("points following the blocks, explicit", ["--set", 'simulation.joint_sampling="step"'])
    if args.detection:
        detection = ["--set", 'simulation.joint_sampling="detection"']
        if not args.no_main_job:
            cases.append(("main job, re-sampled at detection", ["--default"] + detection, None))
        earthquake("re-sampled at detection, explicit",
                   detection + ["--set", 'simulation.damping_scheme="explicit"'])
        earthquake("joints clipped every step, explicit",
                   ["--set", 'simulation.joint_sampling="clip"', "--set", "simulation.detection_travel=1e-12"])
    if args.scene_trigger:
        scene = ["--set", 'simulation.detection_trigger="scene"']
        if not args.no_main_job:
            cases.append(("main job, scene trigger", ["--default"] + scene, None))
        earthquake("scene trigger, explicit", scene)
    if args.only:
        cases = [c for c in cases if any(o in c[0] for o in args.only)]
    samples = {name: [] for name, _, _ in cases}
    top_load = 0.0
    with tempfile.TemporaryDirectory() as tmp:
        for r in range(args.repeat):
            for name, deck, threads in cases:
                top_load = max(top_load, timings_csv.load())
                cmd = [polydem, "run", *deck, "--quiet", "--out", tmp]
                if threads:
                    cmd += ["--threads", str(threads)]
                subprocess.run(cmd, cwd=timings_csv.ROOT, check=True)
                with open(os.path.join(tmp, "summary.json"), encoding="utf-8") as f:
                    s = json.load(f)
                samples[name].append((s["wall_seconds"], s["profile"]["microseconds_per_step"],
                                      s["subcontact_updates_per_second"]))
                print(f"round {r + 1}: {name}: {s['wall_seconds']:.2f} s, "
                      f"{s['profile']['microseconds_per_step']:.1f} us/step", file=sys.stderr)
    note = f"median of {args.repeat} alternating runs; load average up to {top_load:.1f} at a start"
    rows = []
    for name, deck, threads in cases:
        wall = statistics.median(x[0] for x in samples[name])
        us = statistics.median(x[1] for x in samples[name])
        ups = statistics.median(x[2] for x in samples[name])
        command = "polydem run " + " ".join(deck).replace('"', "") + (f" --threads {threads}" if threads else "")
        if threads is None:
            rows.append({"table": "spire_speed", "command": command, "quantity": f"{name}: wall time",
                         "value": f"{wall:.1f}", "unit": "s", "note": note})
        rows.append({"table": "spire_speed", "command": command, "quantity": f"{name}: time per step",
                     "value": f"{us:.1f}", "unit": "µs", "note": note})
        if threads is not None and "explicit" in name:
            rows.append({"table": "spire_speed", "command": command, "quantity": f"{name}: subcontact updates",
                         "value": f"{ups:.3g}", "unit": "per s", "note": note})
    timings_csv.record(rows)
    for r in rows:
        print(f"{r['quantity']}: {r['value']} {r['unit']}")


if __name__ == "__main__":
    main()
