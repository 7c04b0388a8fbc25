#!/usr/bin/env bash
# Builds the libFuzzer targets (fuzz/, clang++, ASan+UBSan) in build-fuzz/ and
# runs each for SECONDS (default 60). docs/robustness.md explains the targets.
#   scripts/fuzz.sh                    every target, 60 s each
#   scripts/fuzz.sh 20                 a quick look: 20 s each
#   scripts/fuzz.sh 3600 deck          one target for an hour (deck|at2|csv_record|obj|ply|vtu)
#   scripts/fuzz.sh replay             only replay fuzz/regressions/ (no fuzzing)
#   FUZZ_SEED=1 scripts/fuzz.sh 60     what .ci/run does: 60 s each, reproducible
# Environment: FUZZ_JOBS=N runs N fuzzing processes per target in fork mode,
# carrying on past findings; POLYDEM_WERROR=OFF if clang warns where g++
# does not; FUZZ_SLOW_S / FUZZ_TIMEOUT_S change the per-input time limits;
# FUZZ_SEED=N fixes libFuzzer's random seed and starts from a fresh corpus
# (build-fuzz/corpus-seed<N>/, emptied first) holding only the seeds below,
# so the run depends only on the repository and ../shared/data: the same
# inputs are tried in the same order (how far it gets in SECONDS depends on
# the machine's speed).
# The growing corpus lives in build-fuzz/corpus/<target>/ (seeded from
# fuzz/corpus/, the example decks and ../shared/data records when present);
# crashes, leaks, out-of-memory, timeouts and slow inputs go to
# build-fuzz/artifacts/<target>/. A finding is printed in full: the end of
# the log (the sanitizer's report and stack) and each new input, readable
# (cat -v) and as base64 (`base64 -d > input` gives the exact bytes back).
# Exit status: 0 when no target found anything, 1 otherwise.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
build=build-fuzz
mode=fuzz
seconds=60
case "${1:-}" in
  replay) mode=replay; shift ;;
  ''|*[!0-9]*) ;;
  *) seconds=$1; shift ;;
esac
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(deck at2 csv_record obj ply vtu)

command -v clang++ > /dev/null || { echo "fuzz: clang++ missing (scripts/setup.sh installs it)" >&2; exit 2; }
mkdir -p "$build"
t0=$SECONDS
cmake -S . -B "$build" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DPOLYDEM_FUZZ=ON -DPOLYDEM_BUILD_TESTS=OFF -DPOLYDEM_WERROR="${POLYDEM_WERROR:-ON}" \
  > "$build/configure.log" 2>&1 || { cat "$build/configure.log"; exit 1; }
cmake --build "$build" -j "$(nproc)" --target "${targets[@]/#/polydem_fuzz_}" 2>&1 | tail -n 30
echo "fuzz: build $((SECONDS - t0)) s"

export OMP_NUM_THREADS=1
# LeakSanitizer on; a UB report is fatal (the build also sets -fno-sanitize-recover).
export ASAN_OPTIONS="detect_leaks=1${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1${UBSAN_OPTIONS:+:$UBSAN_OPTIONS}"

# Prints a finding's input $1: readable and exact (base64).
show_input() {
  local f=$1
  echo "---- $f ($(wc -c < "$f") bytes, sha1 $(sha1sum < "$f" | cut -c1-40)) ----"
  head -c 8192 "$f" | cat -v; echo
  echo "---- base64 (base64 -d > input to recreate it) ----"
  base64 "$f"
  echo "---- end of $f ----"
}

# Seeds for one target into corpus dir $2.
seed() {
  local t=$1 dir=$2
  mkdir -p "$dir"
  cp -n fuzz/corpus/"$t"/* "$dir"/ 2>/dev/null || true
  case "$t" in
    deck) find examples -name '*.toml' | while read -r f; do cp -n "$f" "$dir/example_$(echo "$f" | tr / _)"; done ;;
    at2) for f in ../shared/data/*.AT2 ../shared/data/*.at2; do [ -f "$f" ] && cp -n "$f" "$dir"/; done ;;
    csv_record) for f in ../shared/data/*.csv; do [ -f "$f" ] && cp -n "$f" "$dir"/; done ;;
    obj) find examples -name '*.obj' | while read -r f; do cp -n "$f" "$dir/example_$(echo "$f" | tr / _)"; done ;;
  esac
  return 0
}

status=0
summary=()
for t in "${targets[@]}"; do
  exe="$build/fuzz/polydem_fuzz_$t"
  regress=(fuzz/regressions/"$t"/*)
  if [ "$mode" = replay ]; then
    [ -e "${regress[0]}" ] || { summary+=("$t: no regressions"); continue; }
    # Each reproducer must now run clean (exit 0 without a report).
    if "$exe" -timeout=60 -rss_limit_mb=2048 "${regress[@]}" > "$build/replay_$t.log" 2>&1; then
      summary+=("$t: ${#regress[@]} regression input(s) pass")
    else
      status=1; summary+=("$t: a regression input still fails (see $build/replay_$t.log)")
      tail -n 60 "$build/replay_$t.log"
    fi
    continue
  fi
  corpus="$build/corpus/$t"
  artifacts="$build/artifacts/$t"
  args=(-max_total_time="$seconds" -rss_limit_mb=2048 -artifact_prefix="$artifacts/" -print_final_stats=1)
  if [ -n "${FUZZ_SEED:-}" ]; then
    corpus="$build/corpus-seed$FUZZ_SEED/$t"
    rm -rf "$corpus"
    args+=(-seed="$FUZZ_SEED")
  fi
  seed "$t" "$corpus"
  mkdir -p "$artifacts"
  # Artifacts there before this run: only new ones count as this run's findings.
  declare -A old_artifacts=()
  for f in "$artifacts"/*; do [ -e "$f" ] && old_artifacts["$f"]=1; done
  # Per-input limits, in wall seconds of this instrumented build. The deck
  # reader builds geometry with CGAL, about 25x slower here than in Release
  # (the 330-block example spire: 0.06 s CPU in Release, 1.4 s here; 11-16 s
  # wall with other compiles running), so 1 s of Release work is about 25 s
  # here: save inputs over 10 s as slow units, fail on inputs over 60 s.
  case "$t" in
    deck) args+=(-max_len=8192 -dict=fuzz/deck.dict -report_slow_units="${FUZZ_SLOW_S:-10}" -timeout="${FUZZ_TIMEOUT_S:-60}") ;;
    *) args+=(-max_len=4096 -report_slow_units="${FUZZ_SLOW_S:-1}" -timeout="${FUZZ_TIMEOUT_S:-10}") ;;
  esac
  # FUZZ_JOBS=N: fork mode, N processes, carrying on past findings (each
  # still saved) so that one known bug does not hide the next.
  [ -n "${FUZZ_JOBS:-}" ] && args+=(-fork="$FUZZ_JOBS" -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1)
  echo "fuzz: $t for ${seconds} s${FUZZ_SEED:+, seed $FUZZ_SEED} (corpus $corpus: $(ls "$corpus" | wc -l) inputs)"
  rc=0
  "$exe" "${args[@]}" "$corpus" > "$build/fuzz_$t.log" 2>&1 || rc=$?
  grep -E '^(stat::number_of_executed_units|stat::new_units_added|Slowest unit|Done|==[0-9]+==ERROR|SUMMARY|polydem_fuzz:)' "$build/fuzz_$t.log" || true
  new_found=() found=0 slow=0
  for f in "$artifacts"/*; do
    [ -e "$f" ] && [ -z "${old_artifacts["$f"]:-}" ] || continue
    case "$(basename "$f")" in
      slow-unit-*) slow=$((slow + 1)) ;;
      *) found=$((found + 1)); new_found+=("$f") ;;
    esac
  done
  unset old_artifacts
  if [ "$rc" -ne 0 ] || [ "$found" -gt 0 ]; then
    echo "fuzz: $t: FINDING; the end of $build/fuzz_$t.log:"
    tail -n 80 "$build/fuzz_$t.log"
    for f in "${new_found[@]}"; do show_input "$f"; done
  fi
  # Slow units are wall time, noisy on a busy machine: listed, not failed on.
  # Re-time one with the Release build before calling it a finding.
  note=""
  [ "$slow" -gt 0 ] && note=" ($slow slow input(s) saved, see docs/robustness.md)"
  if [ "$rc" -ne 0 ] || [ "$found" -gt 0 ]; then
    status=1
    summary+=("$t: FINDING (exit $rc, $found new artifact(s) in $artifacts/, log $build/fuzz_$t.log)$note")
  else
    summary+=("$t: clean for ${seconds} s$note")
  fi
done
printf 'fuzz: %s\n' "${summary[@]}"
exit $status
