#!/usr/bin/env bash
# Sanitizer builds and the tests they run (part of scripts/test_all.sh, after the main ctest).
#
#   build-asan  ASan + UBSan (g++, libgomp): the C++ unit tests of ctest but 15 long whole-run
#               tests (listed in run_asan; ELLC_SANITIZE_ALL=1 adds them). Not the Python, FE and
#               LAMMPS tests: those run uninstrumented interpreters and programs (built OFF here).
#   build-tsan  TSan (clang++-15, LLVM's libomp): the engine's thread-determinism tests
#               (test_engine --gtest_filter=EngineDeterminism.*), 2 OpenMP threads. Their dense
#               1000-body run (tests/engine/test_threads.cpp) is the one in which both threads
#               evaluate pairs in the same step; in the 100-body runs the first thread is through
#               the dynamically scheduled pair list before the second has joined.
#
# TSan cannot see the synchronisation inside GCC's libgomp (not instrumented) and reports false
# races at every barrier; LLVM's libomp with its OMPT tool Archer (libarcher.so, package
# libomp-15-dev) tells TSan about OpenMP's barriers, reductions and tasks, so the report is
# clean unless the code races. Before the engine run, a planted race in an OpenMP loop
# (scripts/sanitizers/omp_race.cpp) must be reported and its race-free twin must not: TSan and
# Archer are working, and a clean engine run means something.
#
# Both are Debug builds (ELLC_ASSERT on) at -O1 -g1: -O0 would make the Eigen-heavy tests several
# times slower, and line tables are all a report needs.
#
# Usage: scripts/sanitizers.sh [asan|tsan|all]   (default all)
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/compiler_cache.sh
which=${1:-all}
jobs=$(nproc)
generator=()
command -v ninja >/dev/null && generator=(-G Ninja)
common=(-DCMAKE_BUILD_TYPE=Debug "-DCMAKE_CXX_FLAGS_DEBUG=-O1 -g1"
        -DELLC_BUILD_LAMMPS=OFF -DELLC_BUILD_PYTHON=OFF -DELLC_BUILD_BENCHMARKS=OFF)
seconds() { date +%s; }
# Function names and lines in reports (package llvm-15).
symbolizer=/usr/lib/llvm-15/bin/llvm-symbolizer

run_asan() {
  local start exclude count
  start=$(seconds)
  cmake -S . -B build-asan "${generator[@]}" "${common[@]}" -DELLC_SANITIZE=address,undefined >/dev/null
  cmake --build build-asan -j "$jobs"
  exclude='^(fea|python)\.'  # pytest suites: an uninstrumented interpreter
  # Whole calendering, ensemble and settling runs take 40-210 s each under ASan (1300 s of the
  # suite's 1470 s of CPU), and repeat code paths that the shorter tests of the same suites
  # already run instrumented; their physics is asserted in the Release ctest. ELLC_SANITIZE_ALL=1
  # runs them here too.
  local long_runs='EngineCalendering\.SpringbackPositiveAndSmallerThanElastic|EnsembleOfTwo\.|'
  long_runs+='DemEnsembleCli\.TwoSeedsWriteWhatTwoSingleRunsWrite|ReleasedState\.(ServoUnloads|ALargerResidual|ARelaxationNotReaching)|'
  long_runs+='AnalyseCli\.CalenderingRunAnalysesItsStatesAndTheCheckpointAgrees|'
  long_runs+='LoadingProtocol\.RampedPlateServoHoldAndAReadingAtEquilibrium|EngineSettling\.DepositComesToRest|'
  long_runs+='EngineEnergyBalance\.WallWorkEqualsStoredPlusDissipatedEnergy|ScenarioValidity\.LoadedStateIsTheValidity|'
  long_runs+='Ensemble\.AFailingMemberDoesNotStopTheOthers|ScenarioEnergyBalance\.PlateWorkIsStored|'
  long_runs+='DemCompareCli\.DuctileExampleIsDominatedByPlasticity|'
  long_runs+='RandomPairs\.MillionPairsNoNanNoSilentFailure'
  [[ ${ELLC_SANITIZE_ALL:-0} == 1 ]] || exclude="$exclude|^($long_runs)"
  local listing suites
  listing=$(ctest --test-dir build-asan -N -E "$exclude")
  count=$(sed -n 's/^Total Tests: //p' <<<"$listing")
  suites=$(sed -n 's/^ *Test *#[0-9]*: \([^.]*\)\..*/\1/p' <<<"$listing" | sort -u | tr '\n' ' ')
  echo "== sanitizers: ASan+UBSan (build-asan, Debug -O1, g++): ctest -E '$exclude' (not the Python/FE" \
       "pytest suites, nor the long runs unless ELLC_SANITIZE_ALL=1; LAMMPS not built): $count tests of $suites"
  # ctest -j runs two test processes on two cores: OpenMP threads that spin at barriers would
  # take each other's core (libgomp spins by default), so they wait passively here.
  OMP_WAIT_POLICY=passive \
  ASAN_OPTIONS=detect_leaks=1:strict_string_checks=1:check_initialization_order=1:external_symbolizer_path=$symbolizer \
  UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1:external_symbolizer_path=$symbolizer \
    ctest --test-dir build-asan --output-on-failure -j "$jobs" -E "$exclude"
  echo "== sanitizers: ASan+UBSan passed ($count tests) in $(($(seconds) - start)) s"
}

run_tsan() {
  local start archer llvm=/usr/lib/llvm-15 filter='EngineDeterminism.*'
  start=$(seconds)
  archer=$llvm/lib/libarcher.so
  [[ -f $archer ]] || { echo "sanitizers: $archer missing (apt-get install libomp-15-dev)" >&2; exit 1; }
  # Archer supplies OpenMP's synchronisation to TSan and asks to ignore the accesses inside
  # uninstrumented libraries (libomp itself); a report stops the run.
  export OMP_TOOL_LIBRARIES=$archer OMP_NUM_THREADS=2
  export TSAN_OPTIONS="halt_on_error=1 ignore_noninstrumented_modules=1 external_symbolizer_path=$symbolizer"

  # The self-check: the planted race must be found, its race-free twin must pass.
  local check=build-tsan/omp_race_check
  mkdir -p build-tsan
  clang++-15 -std=c++20 -O1 -g1 -fsanitize=thread -fopenmp=libomp -L$llvm/lib -Wl,-rpath,$llvm/lib \
    scripts/sanitizers/omp_race.cpp -o "$check"
  if "$check" race >build-tsan/omp_race.log 2>&1 || ! grep -q "WARNING: ThreadSanitizer: data race" build-tsan/omp_race.log; then
    cat build-tsan/omp_race.log >&2
    echo "sanitizers: TSan did not report the planted OpenMP race: the TSan run would prove nothing" >&2
    exit 1
  fi
  if ! ARCHER_OPTIONS=verbose=1 "$check" clean >build-tsan/omp_clean.log 2>&1; then
    cat build-tsan/omp_clean.log >&2
    echo "sanitizers: TSan reports a race-free OpenMP loop (libomp/Archer not active?)" >&2
    exit 1
  fi
  grep -q "Archer detected OpenMP application with TSan" build-tsan/omp_clean.log ||
    { echo "sanitizers: Archer was not loaded ($archer)" >&2; exit 1; }
  echo "== sanitizers: TSan self-check: planted OpenMP race reported, race-free twin clean, Archer active"

  cmake -S . -B build-tsan "${generator[@]}" "${common[@]}" -DELLC_SANITIZE=thread \
        -DCMAKE_CXX_COMPILER=clang++-15 >/dev/null
  cmake --build build-tsan -j "$jobs" --target test_engine
  local tests
  tests=$(build-tsan/tests/engine/test_engine --gtest_filter="$filter" --gtest_list_tests | sed -n 's/^  //p')
  if [[ -z $tests ]]; then  # a filter that matches nothing would pass without testing anything
    echo "sanitizers: no test of test_engine matches $filter" >&2
    exit 1
  fi
  echo "== sanitizers: TSan (build-tsan, Debug -O1, clang++-15 + libomp/Archer): test_engine" \
       "--gtest_filter='$filter', OMP_NUM_THREADS=$OMP_NUM_THREADS, $(wc -l <<<"$tests") tests:" $tests
  build-tsan/tests/engine/test_engine --gtest_filter="$filter"
  echo "== sanitizers: TSan passed ($filter) in $(($(seconds) - start)) s"
}

case $which in
  asan) run_asan ;;
  tsan) run_tsan ;;
  all) run_asan; run_tsan ;;
  *) echo "usage: $0 [asan|tsan|all]" >&2; exit 2 ;;
esac
