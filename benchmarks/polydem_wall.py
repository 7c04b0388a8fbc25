# The polydem half of benchmarks/yade_side_by_side.sh (issue 12, "against a peer").
#
#   PYTHONPATH=build/python /usr/bin/python3 benchmarks/polydem_wall.py --courses 10 --bricks 10 --threads 1
#
# Builds the side-by-side running-bond wall with a [[wall]] table (bond
# "stretcher", one leaf: odd courses start and end with a half brick) on a
# fixed base slab, settles it under gravity exactly as yade_wall.py settles
# YADE's (chunks of ~1 ms of motion, at least 20, until every brick is slower
# than --settle-speed or --settle-max has passed), then times a fixed
# simulated interval from the settled state in the same process and prints
# one line "RESULT {json}".
#
# Joint law: kn per unit joint area, ks = ratio * kn, Coulomb friction, no
# cohesion or tension, and polydem's default stiffness-proportional contact
# damping beta = 2.1e-5 s (--beta). Time step: polydem's own (the critical
# step from the joints at each detection, beta included, times the deck's
# safety factor, default 0.8). Threads: --threads with polydem's defaults
# otherwise (the thread governor on, the serial threshold of 2048 subcontacts:
# a small wall runs serially on 2 threads); --fixed-threads turns the
# governor off.
import argparse
import json
import time

import numpy as np
import polydem
from wall_options import add_wall_options

p = argparse.ArgumentParser()
add_wall_options(p, interval=1.0)
p.add_argument("--beta", type=float, default=2.1e-5, help="contact damping beta (s)")
p.add_argument("--threads", type=int, default=1)
p.add_argument("--fixed-threads", action="store_true", help="simulation.adaptive_threads = false")
p.add_argument("--history-interval", type=float, default=0.0,
               help="output.history_interval (s): 0 records the histories and the energy ledger every step")
a = p.parse_args()

L, W, H = a.unit
length = a.bricks * L
deck = f"""
[simulation]
end_time = {a.settle_max + a.interval + 0.01!r}
adaptive_threads = {str(not a.fixed_threads).lower()}

[joint]
normal_stiffness = {a.kn!r}
shear_stiffness = {a.ks_ratio * a.kn!r}
friction_angle = {a.friction!r}
damping = {a.beta!r}

[[block]]
name = "slab"
shape = "box"
size = [{length + L!r}, {3 * W!r}, {2 * H!r}]
center = [{length / 2!r}, 0.0, {-H!r}]
motion = "fixed"

[[wall]]
name = "w"
length = {length!r}
courses = {a.courses}
unit_size = [{L!r}, {H!r}, {W!r}]
bond = "stretcher"
density = {a.density!r}

[output]
snapshot_interval = 0
history_interval = {a.history_interval!r}
"""
run = polydem.Run(polydem.Scene.from_text(deck, name="side-by-side wall"), threads=a.threads)
free = np.asarray(run.free, dtype=bool)


def max_speed(r):
    return float(np.max(np.linalg.norm(np.asarray(r.velocities)[free], axis=1)))


chunk = max(1, int(round(1e-3 / run.dt)))
chunks = 0


def settled(r):
    global chunks
    chunks += 1
    return not (chunks >= 20 and max_speed(r) < a.settle_speed)  # False stops the run


t0 = time.perf_counter()
run.run(until=a.settle_max, callback=settled, every=chunk, progress=False)
settle_wall = time.perf_counter() - t0
settle_time, settled_speed = run.time, max_speed(run)
c = run.contacts()
pairs = {(int(x), int(y)) for x, y in zip(c["reference_block"], c["incident_block"])}
loaded = {(int(x), int(y)) for x, y, f in zip(c["reference_block"], c["incident_block"], c["normal_force"]) if f > 0}

steps0 = run.steps
t0 = time.perf_counter()
run.run(until=settle_time + a.interval, progress=False)
wall = time.perf_counter() - t0
steps = run.steps - steps0
summary = run.finish()
print("RESULT " + json.dumps({
    "code": "polydem", "blocks": int(free.sum()), "dt": run.dt,
    "critical_dt": summary.get("critical_time_step_s"),
    "dt_rule": "0.8 x polydem's critical step (joints, beta included)",
    "damping": "contact damping beta %g s" % a.beta,
    "settle_time": settle_time, "settle_wall": settle_wall, "settled_speed": settled_speed,
    "interval": run.time - settle_time, "steps": steps, "wall": wall,
    "contacts": len(pairs), "contacts_loaded": len(loaded), "subcontacts": len(c["normal_force"]),
    "threads_profile": summary.get("profile", {}).get("threads"),
}), flush=True)
