#!/usr/bin/env bash
# The whole default test suite: set up, build, then ctest without the slow label.
# Tests run as many at a time as there are cores (ctest -j nproc), each
# with OMP_NUM_THREADS=2 (most tests are small scenes that run on one
# thread); the measured wall times are in docs/benchmarks.md ("Build and
# test suite").
#   scripts/test.sh          default suite (< 10 min on 2 cores)
#   scripts/test.sh slow     only the cases labelled slow
# Prints the setup, build and test wall times at the end (.ci/run's log keeps
# them; benchmarks/results/timings.csv has the measured ones).
set -euo pipefail
cd "$(dirname "$0")/.."
t0=$SECONDS
scripts/setup.sh
t1=$SECONDS
scripts/build.sh
t2=$SECONDS
export OMP_NUM_THREADS=2
status=0
if [ "${1:-}" = "slow" ]; then
  ctest --test-dir build -L slow --output-on-failure -j "$(nproc)" || status=$?
else
  ctest --test-dir build -LE slow --output-on-failure -j "$(nproc)" || status=$?
fi
echo "test: setup $((t1 - t0)) s, build $((t2 - t1)) s, tests $((SECONDS - t2)) s"
exit $status
