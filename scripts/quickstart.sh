#!/usr/bin/env bash
# Fresh machine to the main job's verdict, as soon as possible: install what
# the build needs (scripts/setup.sh --minimal), build the polydem program
# only (no tests, no Python module), run the main job: the built-in default
# deck, the Waltham spire under a rising ground acceleration. It ends with
# the run's verdict; the results are in out/main. Extra arguments go to
# `polydem run` (e.g. --verbose, --threads 1).
# scripts/test.sh then installs and builds the rest and runs the test suite.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh --minimal
scripts/build.sh --target polydem
build/polydem run --default --out out/main "$@"
