#!/usr/bin/env bash
# Fresh machine to first result: install what is missing, build, run the main job.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build.sh
build/polydem run --default --out out/main "$@"
