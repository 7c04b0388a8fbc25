#!/usr/bin/env python3
"""A custom load: a horizontal and a vertical record together on a
two-stone column. The deck's [ground_motion] takes the horizontal record
(read by polydem's record reader); the vertical one is given from Python
as a sampled ground acceleration (Run(..., ground_acceleration=...)), added
as a body force. The column runs twice, without and with the vertical
component, and the top stone's displacement is plotted for both.

The record is the 1940 El Centro north-south accelerogram of ../shared/data
(its README); that folder has no vertical component, so the vertical here
is the same record scaled by 2/3 (the usual ratio of vertical to
horizontal peak acceleration): a stand-in to show the mechanics, not a
real vertical record.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/custom_load.py
    PYTHONPATH=build/python /usr/bin/python3 examples/python/custom_load.py --end-time 0.05

Exits with 77 (a skip for CTest) when the record is missing."""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import polydem  # noqa: E402

here = os.path.dirname(os.path.abspath(__file__))
p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
p.add_argument("--end-time", type=float, default=12.0, help="s (default 12: the record's first 12 s)")
p.add_argument("--record", default=os.path.join(here, "..", "..", "..", "shared", "data", "elcentro-1940-ns.AT2"))
p.add_argument("--scale", type=float, default=2.0, help="multiplier of the record (default 2: 0.64 g peak)")
p.add_argument("--out", default="out/python_custom_load")
p.add_argument("--threads", type=int, default=1)
args = p.parse_args()
if not os.path.exists(args.record):
    print(f"custom_load: {args.record} missing (../shared/data): skipped", file=sys.stderr)
    sys.exit(77)


def read_at2(path):
    """A PEER .AT2 record: time (s) and acceleration (g)."""
    with open(path, encoding="utf-8") as f:
        lines = f.read().splitlines()
    header = lines[3].replace(",", " ").split()
    npts = int(header[header.index("NPTS=") + 1])
    dt = float(header[header.index("DT=") + 1])
    acc = np.array([float(x) for line in lines[4:] for x in line.split()][:npts])
    return dt * np.arange(npts), acc


def column():
    return (polydem.Scene(end_time=args.end_time)
            .joint(friction_angle=35.0)
            .add_box("base", size=(1.5, 1.5, 0.3), center=(0, 0, -0.15), motion="fixed")
            .add_box("lower", size=(0.3, 0.3, 0.6), center=(0, 0, 0.3))
            .add_box("upper", size=(0.3, 0.3, 0.6), center=(0, 0, 0.9))
            .ground_motion(kind="record", record=args.record, scale=args.scale, direction=[1.0, 0.0, 0.0])
            .assessment(collapse_displacement=0.2))


t, a = read_at2(args.record)
vertical = np.zeros((len(t), 3))
vertical[:, 2] = (2.0 / 3.0) * args.scale * 9.81 * a  # m/s², upwards

results = {}
for label, extra in (("horizontal", None), ("horizontal + vertical", vertical)):
    run = polydem.Run(column(), out=os.path.join(args.out, label.replace(" + ", "_and_")), threads=args.threads,
                      ground_acceleration=extra, ground_acceleration_time=None if extra is None else t)
    top = run.block("upper")
    times, dx = [], []
    run.run(callback=lambda r: (times.append(r.time),
                                dx.append(1000 * (r.positions[top, 0] - r.initial_positions[top, 0]))),
            every=200, progress=False)
    results[label] = (np.array(times), np.array(dx))
    print(f"{label:>22}: {run.status:<9} peak top displacement {np.abs(dx).max():7.2f} mm, "
          f"residual {dx[-1]:7.2f} mm, {run.steps} steps")

fig, ax = plt.subplots(figsize=(7, 4))
for label, (times, dx) in results.items():
    ax.plot(times, dx, label=label)
ax.set_xlabel("time (s)")
ax.set_ylabel("top stone displacement, x (mm)")
ax.set_title(f"Two-stone column, El Centro NS x{args.scale:g} (vertical: 2/3 of it)")
ax.legend()
ax.grid(True, alpha=0.3)
fig.tight_layout()
fig.savefig(os.path.join(args.out, "column.png"), dpi=100)
print(f"plot in {args.out}/column.png")
