# The YADE half of benchmarks/yade_side_by_side.sh (issue 12, "against a peer").
#
# Run by YADE's own interpreter, not by python3:
#   yade -n -x -j THREADS benchmarks/yade_wall.py --courses 10 --bricks 10 ...
# It builds the running-bond wall of the side-by-side benchmark out of YADE
# Polyhedra bodies, settles it under gravity, then times a fixed simulated
# interval from the settled state and prints one line "RESULT {json}".
#
# The wall is laid out here by hand, unit by unit, as polydem's [[wall]]
# generator lays it (docs/deck.md, bond "stretcher", one leaf): course c has
# its bed at z = c*h; even courses hold `bricks` whole bricks from u = 0 to
# u = bricks*l; odd courses start and end with a half brick (l/2) and hold
# bricks - 1 whole ones between them. The fixed base slab is a polyhedron
# half a brick longer than the wall at each end and three brick widths wide.
#
# YADE's Polyhedra law (Law2_PolyhedraGeom_PolyhedraPhys_Volumetric, YADE
# 2023.02) pushes with Fn = kn_Y * V, V the volume two bodies overlap, and
# kn_Y = 1/(1/E1 + 1/E2) from the materials' `young` E (N/m^3 with the
# default volumePower 1). A flat face of area A pressed by d overlaps V = A*d,
# so Fn = kn_Y*A*d: kn_Y is a stiffness per unit joint area, like polydem's
# kn (Pa/m = N/m^3). Same kn, same static compression of a brick on the slab
# (and of every flat joint): E = 2*kn. The shear force is incremental,
# Fs -= ks_Y * (shear displacement), with ks_Y = 1/(1/(E1 P1) + 1/(E2 P2))
# (P = `poisson`) a stiffness per contact (N/m), not per area; we match
# polydem's ks*A for the bed of a whole brick on the slab (A = l*w): P = 2*ks*A/E.
# Joints of other areas (head joints, half-brick beds) are then stiffer or
# softer in shear than polydem's by A_ref/A; the timed interval is a wall at
# rest, where this changes the cost per step not at all.
#
# Time step: YADE's own estimate for polyhedra (Polyhedra_support.cpp's
# PWaveTimeStep: the radius of the sphere of a body's volume over
# sqrt(young/density), the smallest over the bodies), times --safety. YADE
# 2023.02's Python polyhedra_utils.PWaveTimeStep() is bound to the sphere-only
# Shop::PWaveTimeStep and returns 1.0 with a warning for a scene of
# polyhedra, so this script evaluates the polyhedra formula itself.
# Damping: NewtonIntegrator's local (non-viscous) damping, --damping (YADE's
# default 0.2). Both are stated in the result line.
import argparse
import json
import math
import os
import sys
import time

from yade import polyhedra_utils  # noqa: F401 (YADE's interpreter provides O, Body, ... as builtins)

# YADE runs this file with sys.argv[0] its path (its own __file__ is yade's).
sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from wall_options import add_wall_options  # noqa: E402

p = argparse.ArgumentParser()
add_wall_options(p, interval=0.05)
p.add_argument("--safety", type=float, default=0.8, help="fraction of PWaveTimeStep()")
p.add_argument("--dt", type=float, default=0.0, help="time step (s); 0: --safety x the P-wave estimate")
p.add_argument("--damping", type=float, default=0.2, help="NewtonIntegrator local damping")
p.add_argument("--state", default="", help="settled scene file: loaded if it exists (no settling), "
                                           "else written after settling (O.save)")
a = p.parse_args(sys.argv[1:])

L, W, H = a.unit
young = 2.0 * a.kn
poisson = 2.0 * (a.ks_ratio * a.kn) * (L * W) / young
mat = PolyhedraMat(density=a.density, young=young, poisson=poisson,
                   frictionAngle=math.radians(a.friction))
O.materials.append(mat)


def box(u0, u1, v0, v1, z0, z1):
    return [(x, y, z) for x in (u0, u1) for y in (v0, v1) for z in (z0, z1)]


length = a.bricks * L
slab = polyhedra_utils.polyhedra(mat, v=box(-L / 2, length + L / 2, -1.5 * W, 1.5 * W, -2 * H, 0.0), fixed=True)
O.bodies.append(slab)
bricks = []
for c in range(a.courses):
    if c % 2 == 0:
        joints = [i * L for i in range(a.bricks + 1)]
    else:
        joints = [0.0] + [(i + 0.5) * L for i in range(a.bricks)] + [length]
    for u0, u1 in zip(joints[:-1], joints[1:]):
        bricks.append(O.bodies.append(polyhedra_utils.polyhedra(mat, v=box(u0, u1, -W / 2, W / 2, c * H, (c + 1) * H))))

O.engines = [
    ForceResetter(),
    InsertionSortCollider([Bo1_Polyhedra_Aabb()]),
    InteractionLoop([Ig2_Polyhedra_Polyhedra_PolyhedraGeom()],
                    [Ip2_PolyhedraMat_PolyhedraMat_PolyhedraPhys()],
                    [Law2_PolyhedraGeom_PolyhedraPhys_Volumetric()]),
    NewtonIntegrator(damping=a.damping, gravity=(0, 0, -9.81)),
]
critical = min((3.0 * O.bodies[i].shape.GetVolume() / (4.0 * math.pi)) ** (1.0 / 3.0)
               / math.sqrt(young / a.density) for i in bricks)
O.dt = a.dt if a.dt > 0 else a.safety * critical


def max_speed():
    return max(O.bodies[i].state.vel.norm() for i in bricks)


# Settle: run in chunks of ~1 ms of motion until every brick is slower than
# --settle-speed (after at least 20 chunks, so that gravity has loaded the
# joints) or --settle-max has passed.
# With --state, a wall settled by an earlier run (same arguments but the
# thread count) is loaded instead: YADE's settling is the long part of a run.
chunk = max(1, int(round(1e-3 / O.dt)))
t0 = time.perf_counter()
chunks = 0
reused = bool(a.state) and os.path.exists(a.state)
if reused:
    O.load(a.state)
else:
    while O.time < a.settle_max:
        O.run(chunk, True)
        chunks += 1
        if chunks >= 20 and max_speed() < a.settle_speed:
            break
    if a.state:
        O.save(a.state)
settle_wall = None if reused else time.perf_counter() - t0
settled_speed = max_speed()
settle_time = O.time


def count_contacts():
    # (interactions, those with an overlap volume: the pairs pressed together)
    real = [i for i in O.interactions if i.isReal]
    return len(real), sum(1 for i in real if i.geom.penetrationVolume > 0)


contacts, loaded = count_contacts()

steps = int(math.ceil(a.interval / O.dt))
t0 = time.perf_counter()
O.run(steps, True)
wall = time.perf_counter() - t0
contacts_end, loaded_end = count_contacts()
print("RESULT " + json.dumps({
    "code": "yade", "blocks": len(bricks), "dt": O.dt, "critical_dt": critical,
    "dt_rule": ("given" if a.dt > 0 else "%g x the polyhedra P-wave estimate" % a.safety),
    "damping": "NewtonIntegrator local damping %g" % a.damping,
    "settle_time": settle_time, "settle_wall": settle_wall, "settled_state_reused": reused, "settled_speed": settled_speed,
    "interval": steps * O.dt, "steps": steps, "wall": wall,
    "contacts": contacts, "contacts_loaded": loaded, "contacts_end": contacts_end,
    "contacts_loaded_end": loaded_end, "subcontacts": None,
    "young": young, "poisson": poisson,
}), flush=True)
