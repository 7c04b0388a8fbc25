#!/usr/bin/env bash
# Installs the Debian packages polydem builds with, skipping what is present.
# Needs root (or sudo) only when something is missing.
#   scripts/setup.sh            everything scripts/test.sh and .ci/run need
#   scripts/setup.sh --minimal  what scripts/quickstart.sh needs to configure
#                               the build and build the polydem program
set -euo pipefail
minimal=(
  build-essential cmake pkg-config
  libeigen3-dev libcgal-dev libfcl-dev libccd-dev libhdf5-dev
  libtomlplusplus-dev libcli11-dev libfmt-dev
  # the limit analysis' linear program (studies/limit_analysis.cpp): GLPK, a
  # small stable C library with a sparse simplex and interior point
  libglpk-dev
  # the configure step looks for GoogleTest (the tests are part of the build)
  libgtest-dev libgmock-dev
  # the Python module (python/, docs/python.md): pybind11 and the headers it
  # compiles against (python3-dev: pybind11-dev does not pull it in). With
  # them present the libraries are built as position-independent code, so
  # scripts/test.sh's full build after the quickstart reuses its objects.
  python3 python3-pybind11 python3-dev
)
packages=(
  "${minimal[@]}"
  libbenchmark-dev
  python3-numpy python3-matplotlib python3-h5py
  # pytest for the Python module's tests (tests/python/, run by ctest)
  python3-pytest
  # scripts/fuzz.sh (run by .ci/run): clang++ with libFuzzer (libclang-rt) and
  # clang's OpenMP; llvm for llvm-symbolizer, without which a finding's stack
  # is bare addresses (only recommended by clang, so not pulled in here)
  clang libclang-rt-14-dev libomp-dev llvm
  # polydem sweep across machines: Debian's OpenMPI (mpirun, mpicxx)
  libopenmpi-dev openmpi-bin
)
[ "${1:-}" = "--minimal" ] && packages=("${minimal[@]}")
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages present"
  exit 0
fi
echo "setup: installing ${missing[*]}"
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
