#!/usr/bin/env bash
# The whole default test suite: set up, build, then ctest without the slow label.
# Tests run one at a time: each may use both cores (OMP_NUM_THREADS=2), and
# two OpenMP tests sharing two cores would spin against each other.
#   scripts/test.sh          default suite (< 10 min on 2 cores)
#   scripts/test.sh slow     only the cases labelled slow
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build.sh
export OMP_NUM_THREADS=2
if [ "${1:-}" = "slow" ]; then
  ctest --test-dir build -L slow --output-on-failure -j 1
else
  ctest --test-dir build -LE slow --output-on-failure -j 1
fi
