#!/usr/bin/python3
"""The impact restitution of a rocking prism on polydem's joint springs, in 2D.

    scripts/rocking_impact_model.py                    # the table of docs/structures.md
    scripts/rocking_impact_model.py --dem build/apps/polydem   # ... with the DEM beside it
    scripts/rocking_impact_model.py --pulse [--dem build/apps/polydem]   # the columns under a pulse

Why. A one-piece pillar of octagonal section released at 0.1 rad keeps
0.941 of its angular velocity at the impacts in the DEM, where Housner's
eq. 10 with the octagon's own inertia gives 0.893 (a square pillar: 0.946
against 0.935). This script is an independent model of what the DEM's
contact does, to find out whether that is the contact model or a bug.

What it computes. A rigid prism rocking in the xz-plane about y (three
degrees of freedom: the centroid's x and z and the tilt), standing on a
rigid base through point springs at the vertices of its base polygon, as
contact/contact_patch.cpp and contact/joint_law.hpp make them (read, not
copied): one subcontact per vertex with a tributary area from a fan about
the mean of the vertices; vertices at the same x act as one line.
Per line i of area A_i, overlap u_i and normal velocity:
  normal  F_n = kn A_i u_i + beta kn A_i du_i/dt, never below zero (no tension);
  shear   F_s incremental (ks A_i times the slip velocity times dt), capped at
          tan(phi) kn A_i u_i, plus beta ks A_i times the slip velocity while
          it sticks.
Gravity, leapfrog (velocities at half steps, as the DEM), dt a tenth of
the stiffest contact period over 2 pi, halved without a change in the
fourth digit. The block is released tilted by theta0 on its edge at
+x, just touching; each zero crossing of the tilt is an impact; the
largest tilt of each half-cycle gives the angular velocity at the impacts
by eq. 7's energy integral w^2 = 2 p^2 (cos(alpha - A) - cos alpha), and
the restitution of impact k is w(A_k+1)/w(A_k): the measure of polydem's
housner_restitution check (run/checks.cpp), independent of how long the
elastic impact lasts.

The impulse resultant. If a rigid block rotating about the edge O with
w1 lands flat and leaves rotating about the far edge F (at 2b) with w2,
and the base's impulse has its resultant on the base at distance d from
O, angular momentum about that point is conserved:
  r = w2/w1 = (K + m b (b - d)) / (K - m b (b - d)),   K = I_cm + m h_G^2,
with h_G the centroid's height. d = 2b is Housner's 1 - 2 m b^2 / I_O;
d < 2b keeps more. --impulse prints each line's share of the first
impact's normal impulse and this r for its resultant.

The column under a pulse (--pulse). The one-piece columns of
docs/structures.md (radius 0.3 m, 2.4 m, 4 to 32 sides) under the one-sine
body-force pulse of column_rocking.toml (T_p = 0.5 s): the peak tilt of
the same vertex-spring model started at rest on its springs, and of
Housner's rigid body (eq. 7, semi-implicit steps of 1e-5 s; at each zero
crossing w -> r w) once with eq. 10's r and once with the r of the
vertex-spring model's first impact from 0.05 rad.

Uses only the standard library; --dem runs polydem on the same pillars
(decks written to a temporary folder, or examples/verification/
column_rocking.toml with --set for --pulse) and reads summary.json.
"""

import argparse
import json
import math
import os
import re
import subprocess
import tempfile

G = 9.81


def regular_polygon(n, circumradius, phase):
    return [(circumradius * math.cos(phase + 2 * math.pi * k / n), circumradius * math.sin(phase + 2 * math.pi * k / n))
            for k in range(n)]


def square_with_side_vertices(circumradius, x_fraction, bulge):
    """A square of the given circumradius with two more corners on each of its
    edges parallel to x, at x = +-x_fraction * b, pushed out by `bulge` so that
    they are corners (polydem rejects collinear points)."""
    b = circumradius / math.sqrt(2)
    xi = x_fraction * b
    return [(b, -b), (b, b), (xi, b + bulge), (-xi, b + bulge), (-b, b), (-b, -b), (-xi, -b - bulge), (xi, -b - bulge)]


def prism_section(polygon, height, density=2600.0):
    """Mass, centroidal inertia about y, area, and the base lines [(x, area)]
    of a prism standing on `polygon` (centroid at the origin of the plan)."""
    n = len(polygon)
    area = 0.0
    second_moment = 0.0  # integral of x^2 over the section
    for i in range(n):
        x0, y0 = polygon[i]
        x1, y1 = polygon[(i + 1) % n]
        cross = x0 * y1 - x1 * y0
        area += cross / 2
        second_moment += cross * (x0 * x0 + x0 * x1 + x1 * x1) / 12
    area, second_moment = abs(area), abs(second_moment)
    mass = density * area * height
    inertia = density * height * second_moment + mass * height * height / 12
    cx = sum(p[0] for p in polygon) / n
    cy = sum(p[1] for p in polygon) / n
    tributary = [0.0] * n
    for j in range(n):
        k = (j + 1) % n
        tri = 0.5 * abs((polygon[j][0] - cx) * (polygon[k][1] - cy) - (polygon[j][1] - cy) * (polygon[k][0] - cx))
        tributary[j] += tri / 2
        tributary[k] += tri / 2
    lines = {}
    for (x, _), a in zip(polygon, tributary):
        key = round(x, 12)
        lines[key] = lines.get(key, 0.0) + a
    return mass, inertia, area, sorted(lines.items())


class Block:
    def __init__(self, lines, mass, inertia, height):
        self.lines, self.mass, self.inertia, self.height = lines, mass, inertia, height
        self.b = max(x for x, _ in lines)  # half-width in the rocking plane, pivot at +-b


def line_forces(fx, fz, xs, areas, shear, c, s, zb, Z, vx, vz, w, kn, ks, beta, tan_phi, dt):
    """The vertex lines' spring-dashpots on the block (the joint law of
    contact/joint_law.hpp in 2D: no tension, Coulomb cap on the elastic
    normal force, no shear dashpot while slipping), added to the forces fx,
    fz already acting; updates `shear`. Returns fx, fz, the torque about the
    centroid and each closed line's normal force."""
    torque, normal = 0.0, {}
    for i, px in enumerate(xs):
        rx, rz = px * c + zb * s, -px * s + zb * c
        if Z + rz >= 0.0:
            shear[i] = 0.0
            continue
        u = -(Z + rz)
        vpx, vpz = vx + w * rz, vz - w * rx
        fn_spring = kn * areas[i] * u
        fn = max(0.0, fn_spring - beta * kn * areas[i] * vpz)
        fs = shear[i] - ks * areas[i] * vpx * dt
        cap = tan_phi * fn_spring
        slipping = abs(fs) > cap
        if slipping:
            fs = math.copysign(cap, fs)
        shear[i] = fs
        fxi = fs - (0.0 if slipping else beta * ks * areas[i] * vpx)
        fx += fxi
        fz += fn
        torque += rz * fxi - rx * fn
        normal[i] = fn
    return fx, fz, torque, normal


def rock(block, theta0=0.1, kn=98e9, ks=None, beta=2.1e-5, friction_deg=40.0, impacts=3, impulse=False, dt=None):
    """Free rocking from theta0. Returns the half-cycle amplitudes (impacts + 1
    of them) and, with `impulse`, the normal impulse of each line through the
    first impact (from the first landing-side contact to the moment only the new
    pivot line is closed)."""
    ks = 0.4 * kn if ks is None else ks
    tan_phi = math.tan(math.radians(friction_deg))
    xs = [x for x, _ in block.lines]
    areas = [a for _, a in block.lines]
    m, inertia, zb = block.mass, block.inertia, -block.height / 2
    if dt is None:
        dt = 0.1 / (3 * math.sqrt(kn * sum(areas) / m))
    th = theta0
    X, Z = 0.0, block.b * math.sin(th) - zb * math.cos(th)  # the +x edge just touches z = 0
    vx = vz = w = 0.0
    shear = [0.0] * len(xs)
    J = [0.0] * len(xs)
    in_impact, impact_done = False, not impulse
    new_pivot = xs.index(min(xs))
    amplitudes, peak, last = [], abs(th), th
    while len(amplitudes) < impacts + 1:
        c, s = math.cos(th), math.sin(th)
        fx, fz, torque, normal = line_forces(0.0, -m * G, xs, areas, shear, c, s, zb, Z, vx, vz, w,
                                             kn, ks, beta, tan_phi, dt)
        closed = list(normal)
        if in_impact:
            for i, fn in normal.items():
                J[i] += fn * dt
        if not impact_done:
            if not in_impact and th < 0.01 and any(xs[i] < block.b - 1e-9 for i in closed):
                in_impact = True
            elif in_impact and closed == [new_pivot]:
                in_impact, impact_done = False, True
        vx += fx / m * dt
        vz += fz / m * dt
        w += torque / inertia * dt
        X += vx * dt
        Z += vz * dt
        th_new = th + w * dt
        if (th_new > 0) != (th > 0) and th_new != 0:
            amplitudes.append(peak)
            peak = 0.0
        th = th_new
        peak = max(peak, abs(th))
    return amplitudes, (J if impulse else None)


def rocking_constants(block):
    hg = block.height / 2
    R = math.hypot(block.b, hg)
    alpha = math.atan2(block.b, hg)
    I_O = block.inertia + block.mass * R * R
    p = math.sqrt(block.mass * G * R / I_O)
    return R, alpha, I_O, p


def restitutions(block, amplitudes):
    _, alpha, _, p = rocking_constants(block)
    omega = lambda a: p * math.sqrt(max(0.0, 2 * (math.cos(alpha - a) - math.cos(alpha))))
    return [omega(amplitudes[k + 1]) / omega(amplitudes[k]) for k in range(len(amplitudes) - 1)]


def housner(block):
    _, _, I_O, _ = rocking_constants(block)
    return 1 - 2 * block.mass * block.b ** 2 / I_O


def restitution_for_resultant(block, d):
    K = block.inertia + block.mass * (block.height / 2) ** 2
    e = block.mass * block.b * (block.b - d)
    return (K + e) / (K - e)


def dem_restitutions(exe, polygon, height, theta0, kn, beta, workdir, name):
    """polydem's housner_restitution ratios of the first three impacts for the same pillar."""
    xmax = max(x for x, _ in polygon)
    lift = xmax * math.sin(theta0) + height / 2 * math.cos(theta0) - height / 2
    text = "\n".join([
        "[simulation]", "end_time = 3.0",
        "[joint]", f"normal_stiffness = {kn!r}", "friction_angle = 40.0", f"damping = {beta!r}",
        "[[block]]", 'name = "base"', 'shape = "box"', "size = [3.0, 3.0, 0.5]", "center = [0.0, 0.0, -0.25]",
        'motion = "fixed"',
        "[[block]]", 'name = "pillar"', 'shape = "prism"',
        "polygon = [" + ", ".join(f"[{x!r}, {y!r}]" for x, y in polygon) + "]",
        f"z = [0.0, {height!r}]", f"rotation = [0.0, {math.degrees(theta0)!r}, 0.0]", f"offset = [0.0, 0.0, {lift!r}]",
        "density = 2600.0",
        "[[check]]", 'kind = "housner_restitution"', 'block = "pillar"', "tolerance = 1.0", ""])
    path = os.path.join(workdir, name + ".toml")
    with open(path, "w") as f:
        f.write(text)
    out = os.path.join(workdir, name)
    subprocess.run([exe, "run", path, "--out", out], check=True, capture_output=True)
    with open(os.path.join(out, "summary.json")) as f:
        note = json.load(f)["checks"][0]["note"]
    return [float(v) for v in re.search(r"amplitudes:([-0-9.e ]+);", note).group(1).split()]


def pulse_peak(block, a_g, period=0.5, t_end=2.0, kn=98e9, beta=2.1e-5, friction_deg=40.0):
    """Peak tilt of the vertex-spring model under a one-sine body-force pulse
    a_g g sin(2 pi t / period) along x, from rest on its springs."""
    ks = 0.4 * kn
    tan_phi = math.tan(math.radians(friction_deg))
    xs = [x for x, _ in block.lines]
    areas = [a for _, a in block.lines]
    m, inertia, zb = block.mass, block.inertia, -block.height / 2
    dt = 0.1 / (3 * math.sqrt(kn * sum(areas) / m))
    th, X, Z = 0.0, 0.0, -zb - m * G / (kn * sum(areas))
    vx = vz = w = 0.0
    shear = [0.0] * len(xs)
    peak, t = 0.0, 0.0
    while t < t_end:
        c, s = math.cos(th), math.sin(th)
        fx = m * a_g * G * math.sin(2 * math.pi * t / period) if t < period else 0.0
        fx, fz, torque, _ = line_forces(fx, -m * G, xs, areas, shear, c, s, zb, Z, vx, vz, w,
                                        kn, ks, beta, tan_phi, dt)
        vx += fx / m * dt
        vz += fz / m * dt
        w += torque / inertia * dt
        X += vx * dt
        Z += vz * dt
        th += w * dt
        t += dt
        peak = max(peak, abs(th))
    return peak


def rigid_pulse_peak(block, a_g, r, period=0.5, t_end=2.0, dt=1e-5):
    """Peak tilt of Housner's rigid body (eq. 7) under the same pulse, with
    restitution r at each impact. The body force m a along x is a ground
    acceleration -a."""
    _, alpha, _, p = rocking_constants(block)
    th = w = 0.0
    side, peak, t = 0, 0.0, 0.0
    while t < t_end:
        ground = -a_g * G * math.sin(2 * math.pi * t / period) if t < period else 0.0
        if side == 0:  # at rest until the pulse lifts it
            if abs(ground) > G * math.tan(alpha):
                side = -1 if ground > 0 else 1
            else:
                t += dt
                continue
        w += -p * p * (math.sin(alpha * side - th) + ground / G * math.cos(alpha * side - th)) * dt
        th_new = th + w * dt
        if th_new * side < 0:
            w *= r
            side = -side
        th = th_new
        t += dt
        peak = max(peak, abs(th))
    return peak


def dem_column_peak(exe, sides, a_g, workdir):
    deck = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "examples", "verification",
                        "column_rocking.toml")
    out = os.path.join(workdir, f"column{sides}_{a_g}")
    sets = ["column[1].drums=1", f"column[1].sides={sides}", "column[1].radius=0.3", "column[1].height=2.4",
            f"ground_motion.acceleration_g={a_g}", 'output.histories=["column_drum00.rotation"]']
    cmd = [exe, "run", deck, "--out", out]
    for s in sets:
        cmd += ["--set", s]
    subprocess.run(cmd, capture_output=True)  # the deck's check fails for most of these: not an error here
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)["checks"][0]["measured"]


def pulse_table(exe):
    workdir = tempfile.mkdtemp(prefix="rocking_pulse_") if exe else None
    for sides, a_g in [(4, 0.4), (8, 0.4), (32, 0.4), (16, 0.3)]:
        m, inertia, _, lines = prism_section(regular_polygon(sides, 0.3, math.pi / sides), 2.4)
        block = Block(lines, m, inertia, 2.4)
        amplitudes, _ = rock(block, theta0=0.05, impacts=1)
        r_model = restitutions(block, amplitudes)[0]
        row = (f"{sides:2d} sides, {a_g} g: vertex-spring model {pulse_peak(block, a_g):.4f} rad; rigid body, eq. 10 "
               f"(r = {housner(block):.4f}) {rigid_pulse_peak(block, a_g, housner(block)):.4f}; rigid body, the "
               f"model's r = {r_model:.4f}: {rigid_pulse_peak(block, a_g, r_model):.4f}")
        if exe:
            row += f"; DEM {dem_column_peak(exe, sides, a_g, workdir):.4f}"
        print(row, flush=True)


def cases():
    R, H = 0.3, 2.0
    octagon = regular_polygon(8, R, math.pi / 8)  # a face normal to x: rocks across the flats
    b_oct = R * math.cos(math.pi / 8)
    square = regular_polygon(4, R, math.pi / 4)
    yield "square", square, None, {}
    yield "octagon, across the flats", octagon, None, {}
    yield "octagon, across the corners", regular_polygon(8, R, 0.0), None, {}
    yield "16-gon, across the flats", regular_polygon(16, R, math.pi / 16), None, {}
    yield "32-gon, across the flats", regular_polygon(32, R, math.pi / 32), None, {}
    yield "square + 2 corners on each side (1 mm out)", square_with_side_vertices(R, math.tan(math.pi / 8), 1e-3), None, {}
    yield "octagon's mass, lines at its two edges only", octagon, [(-b_oct, 0.5), (b_oct, 0.5)], {}
    for beta in (0.0, 3e-4, 1e-3):
        yield f"square, beta = {beta:g} s", square, None, {"beta": beta}
        yield f"octagon, beta = {beta:g} s", octagon, None, {"beta": beta}
        if beta == 1e-3:
            yield f"octagon's mass, edges only, beta = {beta:g} s", octagon, [(-b_oct, 0.5), (b_oct, 0.5)], {"beta": beta}
    for kn in (9.8e9, 980e9):
        yield f"square, kn = {kn:g} Pa/m", square, None, {"kn": kn}
        yield f"octagon, kn = {kn:g} Pa/m", octagon, None, {"kn": kn}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--dem", help="a polydem executable: run the DEM on the same pillars and print its ratios too")
    ap.add_argument("--impulse", action="store_true", help="print each line's share of the first impact's impulse")
    ap.add_argument("--pulse", action="store_true", help="the one-piece columns under column_rocking.toml's pulse")
    args = ap.parse_args()
    if args.pulse:
        pulse_table(args.dem)
        return
    H, theta0 = 2.0, 0.1
    workdir = tempfile.mkdtemp(prefix="rocking_impact_") if args.dem else None
    for k, (name, polygon, lumped, kw) in enumerate(cases()):
        m, inertia, area, lines = prism_section(polygon, H)
        if lumped:  # the same block, its whole base area put on the given lines (fractions)
            lines = [(x, f * area) for x, f in lumped]
        block = Block(lines, m, inertia, H)
        amplitudes, J = rock(block, theta0=theta0, impulse=args.impulse, **kw)
        r = restitutions(block, amplitudes)
        row = f"{name:46s} model {' '.join(f'{v:.4f}' for v in r)}  Housner {housner(block):.4f}"
        if args.dem and not lumped:
            dem = dem_restitutions(args.dem, polygon, H, theta0, kw.get("kn", 98e9), kw.get("beta", 2.1e-5), workdir,
                                   f"case{k}")
            row += "  DEM " + " ".join(f"{v:.4f}" for v in dem)
        print(row, flush=True)
        if J:
            total = sum(J)
            d = sum((block.b - x) * j for (x, _), j in zip(lines, J)) / total
            shares = ", ".join(f"{(block.b - x) / (2 * block.b):.3f}: {j / total:.3f}" for (x, _), j in zip(lines, J))
            print(f"    impulse share by distance from the old pivot / 2b: {shares}; resultant d/2b = "
                  f"{d / (2 * block.b):.4f}, r(d) = {restitution_for_resultant(block, d):.4f}")


if __name__ == "__main__":
    main()
