#!/usr/bin/env python3
"""A custom stopping rule: the spire under the default deck's 0.1 g/s
ramp, stopped as soon as any bed joint of the initial mesh opens more than
2 mm (the first crack), instead of at the deck's end time. The callback
reads the joints' openings every 200 steps and returns False to stop.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/stopping_rule.py
    PYTHONPATH=build/python /usr/bin/python3 examples/python/stopping_rule.py --end-time 0.05"""
import argparse

import numpy as np

import polydem

p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
p.add_argument("--end-time", type=float, help="s (default: the deck's 3 s)")
p.add_argument("--opening", type=float, default=0.002, help="m (default 2 mm)")
p.add_argument("--out", default="out/python_stopping_rule")
p.add_argument("--threads", type=int, default=0)
args = p.parse_args()

scene = polydem.Scene.default()
if args.end_time:
    scene = scene.with_set({"simulation.end_time": args.end_time})
run = polydem.Run(scene, out=args.out, threads=args.threads)
names = run.block_names


def first_crack(r):
    j = r.joint_openings()
    bed = np.flatnonzero(j["bed"])
    k = bed[np.argmax(j["opening"][bed])]
    if j["opening"][k] > args.opening:
        print(f"t = {r.time:.4f} s, a_g = {r.ground_acceleration()[0] / 9.81:.4f} g: bed joint "
              f"{names[j['block_a'][k]]} | {names[j['block_b'][k]]} open {1000 * j['opening'][k]:.2f} mm: stop")
        return False
    return True


run.run(callback=first_crack, every=200, progress=False)
if not run.stopped_by_callback:
    print(f"no bed joint opened {1000 * args.opening:g} mm by t = {run.time:.4f} s")
s = run.finish()
print(f"{run.steps} steps; status {s['status']}; results in {args.out}/summary.json and results.h5")
