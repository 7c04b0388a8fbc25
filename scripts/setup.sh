#!/usr/bin/env bash
# Installs the Debian packages polydem builds with, skipping what is present.
# Needs root (or sudo) only when something is missing.
set -euo pipefail
packages=(
  build-essential cmake pkg-config
  libeigen3-dev libcgal-dev libfcl-dev libccd-dev libhdf5-dev
  libtomlplusplus-dev libcli11-dev libfmt-dev
  # the limit analysis' linear program (studies/limit_analysis.cpp): GLPK, a
  # small stable C library with a sparse simplex and interior point
  libglpk-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  python3 python3-numpy python3-matplotlib python3-h5py
  # the Python module (python/, docs/python.md): pybind11 and the headers
  # it compiles against (python3-dev: pybind11-dev does not pull it in),
  # and pytest for its tests (tests/python/, run by ctest)
  python3-pybind11 python3-dev python3-pytest
  # scripts/fuzz.sh (run by .ci/run): clang++ with libFuzzer (libclang-rt) and
  # clang's OpenMP; llvm for llvm-symbolizer, without which a finding's stack
  # is bare addresses (only recommended by clang, so not pulled in here)
  clang libclang-rt-14-dev libomp-dev llvm
  # polydem sweep across machines: Debian's OpenMPI (mpirun, mpicxx)
  libopenmpi-dev openmpi-bin
)
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
