#!/usr/bin/env bash
# Configures and builds polydem in build/ (Release).
#   scripts/build.sh [--target T]... [CMAKE_ARGS...]
# --target builds only that target and what it needs (scripts/quickstart.sh
# builds `polydem` alone); without one, everything: the program, the Python
# module, the tests and the benchmarks. Other arguments go to cmake's
# configure step, e.g. -DCMAKE_CXX_COMPILER_LAUNCHER=ccache.
set -euo pipefail
cd "$(dirname "$0")/.."
targets=()
configure=()
while [ $# -gt 0 ]; do
  case "$1" in
    --target) targets+=(--target "$2"); shift 2 ;;
    *) configure+=("$1"); shift ;;
  esac
done
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "${configure[@]}" > build.log 2>&1 || { cat build.log; exit 1; }
cmake --build build -j "$(nproc)" "${targets[@]}" 2>&1 | tail -n 50
