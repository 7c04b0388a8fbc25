#!/usr/bin/env bash
# Builds the benchmarks in build-bench/ (Release) and runs them, refreshing
# benchmarks/results/error_vs_time.csv and benchmarks/results/throughput.csv.
#   scripts/bench.sh              both benchmarks
#   scripts/bench.sh error        only polydem_error_vs_time
#   scripts/bench.sh throughput   only polydem_throughput
#   scripts/bench.sh step [DECK...] polydem_step_bound: the automatic step's
#                                 bound against the exact frequency (not
#                                 a timing; not part of `all`)
#   scripts/bench.sh jump         polydem_redetection_jump: how much a
#                                 joint's force jumps at a re-detection,
#                                 per joint model (not a timing; not
#                                 part of `all`)
# Extra arguments after the first go to the benchmark(s), e.g.
#   scripts/bench.sh throughput --repeat 5
# Timings are wall-clock: run on a quiet machine (compiles running alongside
# make them noisy; the throughput keeps the best of its repeats).
set -euo pipefail
cd "$(dirname "$0")/.."
which="${1:-all}"
[ $# -gt 0 ] && shift
build=build-bench
mkdir -p "$build"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release > "$build/configure.log" 2>&1 || { cat "$build/configure.log"; exit 1; }
cmake --build "$build" -j "$(nproc)" --target polydem_error_vs_time polydem_throughput polydem_step_bound \
  polydem_redetection_jump 2>&1 | tail -n 20
case "$which" in
  all)        "$build/benchmarks/polydem_error_vs_time" "$@"
              "$build/benchmarks/polydem_throughput" "$@" ;;
  error)      "$build/benchmarks/polydem_error_vs_time" "$@" ;;
  throughput) "$build/benchmarks/polydem_throughput" "$@" ;;
  step)       "$build/benchmarks/polydem_step_bound" "$@" ;;
  jump)       "$build/benchmarks/polydem_redetection_jump" "$@" ;;
  *) echo "usage: scripts/bench.sh [all|error|throughput|step|jump] [args...]" >&2; exit 2 ;;
esac
