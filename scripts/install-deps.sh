#!/usr/bin/env bash
# Installs the Debian packages vivp builds against, and only those that are missing
# (install-deps.sh [--distributed]).
# Idempotent and non-interactive: when everything is present it makes no apt call at all.
set -euo pipefail

packages=(
  build-essential clang libclang-rt-dev cmake pkg-config
  libeigen3-dev libceres-dev libgoogle-glog-dev
  libboost-dev libboost-test-dev libboost-iostreams-dev libboost-system-dev libboost-filesystem-dev
  liblapack-dev libgnuplot-iostream-dev gnuplot-nox
  libtomlplusplus-dev libcli11-dev nlohmann-json3-dev libginac-dev
  libsuitesparse-dev libfftw3-dev libhdf5-dev hdf5-tools
  # An optimized BLAS for CHOLMOD's supernodal factorization (the charged
  # march in 2 + 1 D): 4-7× faster than the reference BLAS or ATLAS there.
  libopenblas0-pthread
)

# `--distributed` (make test): also OpenMPI and FFTW's MPI transforms, for
# the march across ranks (docs/distributed.md). `make demo` does not need
# them: without them the build runs every field march on one process.
if [[ ${1:-} == --distributed ]]; then
  packages+=(openmpi-bin libopenmpi-dev libfftw3-mpi-dev)
fi

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$p")
done

if [[ ${#missing[@]} -eq 0 ]]; then
  exit 0
fi

echo "vivp: installing missing Debian packages: ${missing[*]}" >&2
sudo=()
if [[ $(id -u) -ne 0 ]]; then
  command -v sudo >/dev/null || { echo "vivp: need root (or sudo) to install: ${missing[*]}" >&2; exit 1; }
  sudo=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -qq
"${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
