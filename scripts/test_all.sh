#!/usr/bin/env bash
# The README's test command: installs what is missing, builds everything, runs every test
# (C++ unit and physics tests, CLI, geometry, engine, LAMMPS under MPI, Python, FE smoke run).
set -euo pipefail
cd "$(dirname "$0")/.."
began=$(date +%s)
bash scripts/setup.sh
stage=$(date +%s)
bash scripts/build.sh
echo "== build took $(($(date +%s) - stage)) s"
# mpirun refuses to run as root unless told; CI runs as root.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
stage=$(date +%s)
ctest --test-dir build --output-on-failure -j "$(nproc)"
echo "== ctest took $(($(date +%s) - stage)) s"

# Guard rails, after the tests above: formatting, clang-tidy, and the ASan+UBSan and TSan
# builds with their tests (scripts/sanitizers.sh says which subset), and fuzzing of the input
# readers (scripts/fuzz.sh: its build and 30 s per target, two at a time). Each runs even if an
# earlier one failed; the command fails if any did. The build scripts compile through ccache and
# tidy.sh skips files found clean before (scripts/compiler_cache.sh, scripts/tidy_cache.py).
# Measured 2026-12-02, fresh clone of main on the 2-core machine that had built the same sources
# (as CI's clone is): 543 s in all (build 37 s, ctest 99 s, tidy 169 s with 17 files not yet
# recorded (5 s when all are), ASan+UBSan 108 s, TSan 18 s, fuzz 109 s). A new machine compiles
# everything four times and tidies every file: about 40 min, estimated from the stage times.
# ELLC_SKIP_GUARDS=1 skips them for a quick local run (CI does not).
if [[ ${ELLC_SKIP_GUARDS:-0} == 1 ]]; then
  echo "== guard rails skipped (ELLC_SKIP_GUARDS=1)"
  exit 0
fi
failed=()
for guard in check_format tidy sanitizers fuzz; do
  start=$(date +%s)
  echo "== guard: scripts/${guard}.sh"
  bash "scripts/${guard}.sh" || failed+=("$guard")
  echo "== guard: scripts/${guard}.sh took $(($(date +%s) - start)) s"
done
if ((${#failed[@]} > 0)); then
  echo "== guard rails failed: ${failed[*]}" >&2
  exit 1
fi
echo "== guard rails passed: format, clang-tidy, ASan+UBSan, TSan, fuzzing"
echo "== test_all.sh took $(($(date +%s) - began)) s"
