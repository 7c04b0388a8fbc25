#!/usr/bin/env bash
# The default test suite (ctest -LE slow) built with AddressSanitizer and
# UndefinedBehaviorSanitizer (POLYDEM_SANITIZE=ON, RelWithDebInfo) in
# build-asan/. Any sanitizer report fails the test it happens in.
#   scripts/sanitize.sh             build and run the default suite
#   scripts/sanitize.sh -R deck     extra arguments go to ctest
# Prints the build and test wall times at the end; docs/robustness.md has
# the times measured on the 2-core build machine.
set -euo pipefail
cd "$(dirname "$0")/.."
build=build-asan
mkdir -p "$build"
t0=$SECONDS
# -Wno-maybe-uninitialized: with -fsanitize at -O2, g++ 12 warns falsely inside
# <regex> (std::function in regex_automaton.h, from tests/apps/run_command_test.cpp),
# which -Werror turns into a build failure; the plain build keeps the warning.
cmake -S . -B "$build" -DPOLYDEM_SANITIZE=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS="-Wno-maybe-uninitialized" > "$build/configure.log" 2>&1 || { cat "$build/configure.log"; exit 1; }
cmake --build "$build" -j "$(nproc)" 2>&1 | tail -n 30
build_s=$((SECONDS - t0))
# detect_leaks: LeakSanitizer at exit; halt_on_error + print_stacktrace: the
# first UB report stops the test with a stack (the build already compiles
# with -fno-sanitize-recover=all; this covers anything linked in recoverable).
export ASAN_OPTIONS="detect_leaks=1:strict_string_checks=1:check_initialization_order=1${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1${UBSAN_OPTIONS:+:$UBSAN_OPTIONS}"
export OMP_NUM_THREADS=2
t1=$SECONDS
status=0
ctest --test-dir "$build" -LE slow --output-on-failure -j 1 "$@" || status=$?
test_s=$((SECONDS - t1))
echo "sanitize: build ${build_s} s, tests ${test_s} s (ctest -LE slow, OMP_NUM_THREADS=2)"
exit $status
