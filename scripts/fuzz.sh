#!/usr/bin/env bash
# libFuzzer runs of the input readers (tests/fuzz/, docs/input_limits.md "Fuzzing"); a guard rail
# of scripts/test_all.sh.
#
# Builds build-fuzz (clang++-15, ASan + UBSan, libFuzzer coverage, Debug -O1 -g1; only the fuzz
# targets and what they link), then fuzzes each target for ELLC_FUZZ_SECONDS (default 30), two at
# a time, starting from the committed seed corpus and the regression inputs. New corpus entries go
# to build-fuzz/corpus/<target>/ (the committed corpus is not touched). Any finding (a crash, a
# sanitizer report, a timeout of 10 s, a leak, or a broken promise of fuzz_support.hpp) fails the
# script and leaves the input in build-fuzz/findings/<target>/: reproduce it with
#   build-fuzz/tests/fuzz/fuzz_<target> build-fuzz/findings/<target>/crash-...
# and, with the fix, add it to tests/fuzz/regressions/<target>/ (ctest replays those).
#
# Usage: scripts/fuzz.sh [target...]   (default: case poses scenario checkpoint fit_table)
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/compiler_cache.sh
seconds=${ELLC_FUZZ_SECONDS:-30}
targets=("$@")
((${#targets[@]} > 0)) || targets=(case poses scenario checkpoint fit_table)
start=$(date +%s)
generator=()
command -v ninja >/dev/null && generator=(-G Ninja)
symbolizer=/usr/lib/llvm-15/bin/llvm-symbolizer
ls /usr/lib/llvm-15/lib/clang/*/lib/linux/libclang_rt.fuzzer-*.a >/dev/null 2>&1 ||
  { echo "fuzz: libFuzzer missing (apt-get install libfuzzer-15-dev clang-15)" >&2; exit 1; }

cmake -S . -B build-fuzz "${generator[@]}" -DCMAKE_CXX_COMPILER=clang++-15 -DCMAKE_BUILD_TYPE=Debug \
  "-DCMAKE_CXX_FLAGS_DEBUG=-O1 -g1" -DELLC_SANITIZE=address,undefined -DELLC_BUILD_FUZZERS=ON \
  -DELLC_BUILD_TESTS=OFF -DELLC_BUILD_BENCHMARKS=OFF -DELLC_BUILD_LAMMPS=OFF -DELLC_BUILD_PYTHON=OFF >/dev/null
cmake --build build-fuzz -j "$(nproc)" --target "${targets[@]/#/fuzz_}"
echo "== fuzz: built in $(($(date +%s) - start)) s; fuzzing ${targets[*]} for ${seconds} s each"

fuzz_one() {
  local target=$1 seconds=$2 log
  mkdir -p "build-fuzz/corpus/$target" "build-fuzz/findings/$target"
  log="build-fuzz/findings/$target/fuzz.log"
  if OMP_NUM_THREADS=1 \
    ASAN_OPTIONS=external_symbolizer_path=$symbolizer \
    UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1:external_symbolizer_path=$symbolizer \
    "build-fuzz/tests/fuzz/fuzz_$target" "build-fuzz/corpus/$target" "tests/fuzz/corpus/$target" \
      "tests/fuzz/regressions/$target" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
      -max_len=4096 -artifact_prefix="build-fuzz/findings/$target/" -print_final_stats=1 >"$log" 2>&1; then
    echo "== fuzz: $target clean ($(sed -n 's/^stat::number_of_executed_units: *//p' "$log") inputs)"
  else
    echo "== fuzz: $target FOUND A PROBLEM (build-fuzz/findings/$target/):" >&2
    grep -E "ERROR|runtime error|fuzz finding|Test unit written|SUMMARY" "$log" | head -20 >&2
    return 1
  fi
}
export -f fuzz_one
export symbolizer
status=0
printf '%s\n' "${targets[@]}" | xargs -P "$(nproc)" -I{} bash -c "fuzz_one {} $seconds" || status=1
echo "== fuzz: ${#targets[@]} targets in $(($(date +%s) - start)) s"
exit $status
