#!/usr/bin/env bash
# The README's test command: installs what is missing, builds everything, runs every test
# (C++ unit and physics tests, CLI, geometry, engine, LAMMPS under MPI, Python, FE smoke run).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
# mpirun refuses to run as root unless told; CI runs as root.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
ctest --test-dir build --output-on-failure -j "$(nproc)"
