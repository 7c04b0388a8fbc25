#!/usr/bin/env bash
# polydem against YADE (Debian package `yade`, Polyhedra bodies) on the same
# running-bond wall, side by side in one run (issue 12, "Against a peer").
# The work is done by benchmarks/yade_side_by_side.py (the table; the wall,
# the stiffness mapping, time steps and damping are described in its header,
# in polydem_wall.py's and yade_wall.py's, and in docs/benchmarks.md "Against
# YADE"). This wrapper picks Debian's /usr/bin/python3, the interpreter
# polydem's Python module is built for.
#
# Usage: benchmarks/yade_side_by_side.sh [--build DIR] [--sizes 10x10,20x20,40x25]
#          [--threads 1,2] [--polydem-interval S] [--yade-interval S]
#          [--settle-max S] [--settle-speed V] [--yade-dt S] [--polydem-history-interval S]
#          [--quick] [--no-yade]
#          [--csv FILE]
# Without yade on PATH it says so, runs the polydem half only and exits 0.
set -euo pipefail
cd "$(dirname "$0")/.."
exec /usr/bin/python3 benchmarks/yade_side_by_side.py "$@"
