# The running-bond wall's options, shared by the two halves of
# benchmarks/yade_side_by_side.sh (polydem_wall.py under python3,
# yade_wall.py under YADE's interpreter): both must read the same wall, the
# same joint and the same settling and timing from the same flags.


def add_wall_options(p, interval):
    """The wall, joint, settling and timing flags; `interval` is the timed
    simulated interval's default (s), which differs between the codes."""
    p.add_argument("--courses", type=int, required=True)
    p.add_argument("--bricks", type=int, required=True, help="whole bricks per even course")
    p.add_argument("--unit", type=float, nargs=3, default=[0.3, 0.3, 0.15], metavar=("L", "W", "H"),
                   help="brick length along the wall, width through it, height (m)")
    p.add_argument("--kn", type=float, default=1e10, help="normal stiffness per unit joint area (Pa/m)")
    p.add_argument("--ks-ratio", type=float, default=0.4)
    p.add_argument("--friction", type=float, default=30.0, help="friction angle (degrees)")
    p.add_argument("--density", type=float, default=2600.0)
    p.add_argument("--settle-max", type=float, default=0.5, help="settle at most this long (simulated s)")
    p.add_argument("--settle-speed", type=float, default=1e-3,
                   help="settled: every brick slower than this (m/s)")
    p.add_argument("--interval", type=float, default=interval, help="timed simulated interval (s)")
