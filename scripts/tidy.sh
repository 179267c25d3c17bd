#!/usr/bin/env bash
# clang-tidy-15 over the library sources (src/ellc/**.cpp, and through them the library's
# headers) with the checks of .clang-tidy. Fails on any finding. Files may be given to check
# only those: scripts/tidy.sh src/ellc/engine/simulation.cpp
#
# The compile commands come from build-tidy, configured (not built) as a Debug build so that
# ELLC_ASSERT conditions are real code to the checks; LAMMPS, Python, benchmarks and tests off.
set -euo pipefail
cd "$(dirname "$0")/.."
clang_tidy=${CLANG_TIDY:-clang-tidy-15}
generator=()
command -v ninja >/dev/null && generator=(-G Ninja)
cmake -S . -B build-tidy "${generator[@]}" -DCMAKE_BUILD_TYPE=Debug -DCMAKE_EXPORT_COMPILE_COMMANDS=ON \
      -DELLC_BUILD_TESTS=OFF -DELLC_BUILD_LAMMPS=OFF -DELLC_BUILD_PYTHON=OFF -DELLC_BUILD_BENCHMARKS=OFF >/dev/null

if (($# > 0)); then
  files=("$@")
else
  mapfile -t files < <(git ls-files -- 'src/ellc/**.cpp')
fi
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
start=$(date +%s)
# One clang-tidy per file, $(nproc) at a time; each writes its own report.
printf '%s\n' "${files[@]}" | xargs -P "$(nproc)" -I{} sh -c \
  '"$1" -p build-tidy --quiet "$2" >"$3/$(echo "$2" | tr / _).log" 2>&1 || true' _ "$clang_tidy" {} "$out"
# Findings in headers are reported once per including source: count each location once.
findings=$(cat "$out"/*.log | grep -E '^[^ ]+:[0-9]+:[0-9]+: (warning|error):' | sort -u || true)
seconds=$(($(date +%s) - start))
if [[ -n $findings ]]; then
  cat "$out"/*.log | grep -vE '^[0-9]+ warnings? (and [0-9]+ errors? )?generated\.$' >&2
  echo "tidy: $(wc -l <<<"$findings") findings in ${#files[@]} files (${seconds} s):" >&2
  echo "$findings" >&2
  exit 1
fi
echo "tidy: ${#files[@]} files clean ($("$clang_tidy" --version | grep -o 'version [0-9.]*'), ${seconds} s)"
