#!/usr/bin/env bash
# clang-tidy-15 over the library sources (src/ellc/**.cpp, and through them the library's
# headers) with the checks of .clang-tidy. Fails on any finding. Files may be given to check
# only those: scripts/tidy.sh src/ellc/engine/simulation.cpp
#
# The compile commands come from build-tidy, configured (not built) as a Debug build so that
# ELLC_ASSERT conditions are real code to the checks; LAMMPS, Python, benchmarks and tests off.
#
# A file found clean is not checked again until it, a header it includes, its compile command,
# .clang-tidy or clang-tidy's version changes (scripts/tidy_cache.py; the cache is
# ${XDG_CACHE_HOME:-~/.cache}/ellc-tidy, shared by clones; ELLC_TIDY_CACHE=0 checks every file).
set -euo pipefail
shopt -s nullglob  # no report files when every file was unchanged
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
version=$("$clang_tidy" --version | grep -o 'version [0-9.]*')
cache=${XDG_CACHE_HOME:-$HOME/.cache}/ellc-tidy
all=${#files[@]}
declare -A keys=()
if [[ ${ELLC_TIDY_CACHE:-1} != 0 ]]; then
  # The files whose key has no clean record (one "file<TAB>key" line each).
  pending=$(python3 scripts/tidy_cache.py keys build-tidy "$cache" "$version" "${files[@]}")
  files=()
  while IFS=$'\t' read -r file key; do
    [[ -n $file ]] || continue
    files+=("$file")
    keys[$file]=$key
  done <<<"$pending"
fi
# One clang-tidy per file, $(nproc) at a time; each writes its own report.
if ((${#files[@]} > 0)); then
  printf '%s\n' "${files[@]}" | xargs -P "$(nproc)" -I{} sh -c \
    '"$1" -p build-tidy --quiet "$2" >"$3/$(echo "$2" | tr / _).log" 2>&1 || true' _ "$clang_tidy" {} "$out"
fi
# Findings in headers are reported once per including source: count each location once.
finding='^[^ ]+:[0-9]+:[0-9]+: (warning|error):'
findings=$(cat "$out"/*.log /dev/null | grep -E "$finding" | sort -u || true)
seconds=$(($(date +%s) - start))
# Record the files whose own report is clean, also when others have findings (a finding in a
# header shows in the report of every file that includes it, so those stay unrecorded).
clean_keys=()
for file in "${files[@]}"; do
  [[ ${keys[$file]:-none} != none ]] || continue
  grep -qE "$finding" "$out/$(echo "$file" | tr / _).log" || clean_keys+=("${keys[$file]}")
done
((${#clean_keys[@]} == 0)) || python3 scripts/tidy_cache.py mark "$cache" "${clean_keys[@]}"
if [[ -n $findings ]]; then
  cat "$out"/*.log | grep -vE '^[0-9]+ warnings? (and [0-9]+ errors? )?generated\.$' >&2
  echo "tidy: $(wc -l <<<"$findings") findings in ${#files[@]} files (${seconds} s):" >&2
  echo "$findings" >&2
  exit 1
fi
echo "tidy: $all files clean ($version, ${seconds} s; $((all - ${#files[@]})) unchanged since a clean check)"
