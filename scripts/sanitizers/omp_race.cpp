// Self-check of the TSan build (scripts/sanitizers.sh): TSan with LLVM's libomp and Archer must
// report a planted race in an OpenMP loop and must not report the same work done race-free.
//   omp_race race    a shared counter incremented in a parallel loop (expected: a TSan report)
//   omp_race clean   the same sum by reduction, and one parallel loop reading what another
//                    wrote (the joins and barriers a false positive would come from)
#include <omp.h>

#include <cstdio>
#include <cstring>
#include <vector>

int main(int argc, char** argv) {
  const bool race = argc > 1 && std::strcmp(argv[1], "race") == 0;
  omp_set_num_threads(2);
  constexpr int kCount = 1 << 14;
  std::vector<double> values(kCount);
#pragma omp parallel for schedule(static)
  for (int k = 0; k < kCount; ++k) values[k] = 0.5 * k;
  long counter = 0;
  if (race) {  // static halves: no synchronisation between the two threads' increments at all
#pragma omp parallel for schedule(static)
    for (int k = 0; k < kCount; ++k)
      if (values[kCount - 1 - k] >= 0.0) ++counter;  // unsynchronised read-modify-write
  } else {
#pragma omp parallel for schedule(dynamic, 256) reduction(+ : counter)
    for (int k = 0; k < kCount; ++k)
      if (values[kCount - 1 - k] >= 0.0) ++counter;
  }
  std::printf("counter = %ld of %d\n", counter, kCount);
  return 0;
}
