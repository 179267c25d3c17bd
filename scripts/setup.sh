#!/usr/bin/env bash
# Installs every Debian package ellc needs to build, test, plot, run LAMMPS and the FE reference,
# and to check the Debian package.
# Idempotent: packages already present are skipped by apt-get. Needs root (or sudo).
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config git
  ccache  # scripts/compiler_cache.sh: rebuilds and CI's fresh clones reuse compiled objects
  libeigen3-dev libcli11-dev libtomlplusplus-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  pybind11-dev python3-dev python3-numpy python3-matplotlib python3-pytest
  libceres-dev
  lammps liblammps-dev libopenmpi-dev openmpi-bin libfmt-dev
  gmsh python3-gmsh calculix-ccx
  clang-format-15 clang-tidy-15 clang-15 libomp-15-dev llvm-15  # guard rails; TSan with libomp, llvm-symbolizer
  debootstrap  # the clean Debian root of scripts/check_deb.sh
  libfuzzer-15-dev  # scripts/fuzz.sh (with clang-15)
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]} == 0)); then
  echo "setup: all ${#packages[@]} packages already installed"
  exit 0
fi

sudo_cmd=()
if [[ $(id -u) -ne 0 ]]; then sudo_cmd=(sudo); fi
export DEBIAN_FRONTEND=noninteractive
echo "setup: installing ${missing[*]}"
"${sudo_cmd[@]}" apt-get update -q
"${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
