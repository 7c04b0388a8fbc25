#!/usr/bin/env bash
# More threads must never be slower (issue 12). Runs the spire's earthquake
# deck for a short time on 1 thread, on 2 threads with the thread governor
# off (simulation.adaptive_threads=false) and on 2 threads as a user gets them
# (the governor on), each alone and beside one competing single-threaded
# process (a second polydem run of the same deck, as `polydem sweep --jobs 2`
# or a user with a second job open would have), and prints the subcontact
# updates per second (median of REPEAT runs) as a markdown table.
#
# Usage: benchmarks/competing_process.sh [BUILD_DIR] [END_TIME] [REPEAT] [DECK]
# DECK defaults to the spire's earthquake deck; a small scene, e.g.
# examples/verification/dry_stone_wall.toml (52 stones, steps of ~10 µs),
# shows the short steps and the detections of a serial scene. The
# competitor is always the spire on one thread.
# Run it on an otherwise quiet machine (check `uptime`): the competitor is
# the only other load it should see.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
end_time=${2:-0.1}
repeat=${3:-3}
polydem="$build/polydem"
deck=${4:-examples/spire/earthquake.toml}
competitor_deck=examples/spire/earthquake.toml
tmp=$(mktemp -d)
stop_competitor() {
  kill "${competitor:-}" 2>/dev/null || true
  pkill -f "$tmp/competitor" 2>/dev/null || true
  sleep 1
}
trap 'stop_competitor; rm -rf "$tmp"' EXIT

rate() {  # threads adaptive -> subcontact updates per second of one run
  "$polydem" run "$deck" --quiet --threads "$1" --set simulation.end_time="$end_time" \
    --set simulation.adaptive_threads="$2" --set output.snapshot_interval=0 --out "$tmp/run" > /dev/null
  /usr/bin/python3 -c "import json; print(json.load(open('$tmp/run/summary.json'))['subcontact_updates_per_second'])"
}

median() { sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }

start_competitor() {
  ( while true; do "$polydem" run "$competitor_deck" --quiet --threads 1 --set simulation.end_time=10 \
      --out "$tmp/competitor" > /dev/null 2>&1 || true; done ) &
  competitor=$!
  sleep 2
}

echo "# $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), load $(cut -d' ' -f1-3 /proc/loadavg)"
echo "# polydem $(git rev-parse --short HEAD 2>/dev/null || echo '?'), deck $deck, $end_time s, median of $repeat"
echo
echo "| competitor | 1 thread | 2 threads, governor off | 2 threads, governor on (default) |"
echo "|---|---|---|---|"
for load in none polydem; do
  [ "$load" = polydem ] && start_competitor
  row="| $load"
  for cfg in "1 false" "2 false" "2 true"; do
    set -- $cfg
    r=$(for _ in $(seq "$repeat"); do rate "$1" "$2"; done | median)
    row="$row | $(printf '%.3g' "$r")"
  done
  echo "$row |"
  if [ "$load" = polydem ]; then stop_competitor; fi
done
