// narrow_phase_property [--pairs N] [--seed S]: the narrow phase's property test over the
// documented shape range (tests/geometry/narrow_phase_property.hpp, docs/geometry.md §6).
// The documented run (not a CI step; a few seconds of CPU):
//   nice -n 10 build/tests/geometry/narrow_phase_property --pairs 1000000
// Exit code 0 when no pair that must be solved (separated, grazing, overlap ≤ 10 % of the
// smallest semi-axis) failed, was non-finite, unverified or swap-asymmetric; 1 otherwise.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "narrow_phase_property.hpp"

int main(int argc, char** argv) {
  long pairs = 1'000'000;
  unsigned long long seed = 19;
  for (int arg = 1; arg < argc; ++arg) {
    const bool has_value = arg + 1 < argc;
    if (std::strcmp(argv[arg], "--pairs") == 0 && has_value) {
      pairs = std::strtol(argv[++arg], nullptr, 10);
    } else if (std::strcmp(argv[arg], "--seed") == 0 && has_value) {
      seed = std::strtoull(argv[++arg], nullptr, 10);
    } else {
      std::fprintf(stderr, "usage: narrow_phase_property [--pairs N] [--seed S]\n");
      return 2;
    }
  }
  if (pairs < 1) {
    std::fprintf(stderr, "narrow_phase_property: --pairs must be a number >= 1\n");
    return 2;
  }
  const ellc::test::PropertyReport report = ellc::test::run_narrow_phase_property(pairs, seed);
  std::fputs(report.text().c_str(), stdout);
  return report.required_failures() == 0 ? 0 : 1;
}
