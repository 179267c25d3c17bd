// Fuzz target: the poses file of `ellc geometry` (cases/poses_file.hpp). Bytes → TOML → validated
// PosesCase → the narrow phase (pair or wall) → the law at the overlap found. Crashes, sanitizer
// reports and hangs are findings here; whether `ellc geometry` prints finite numbers is its own
// check (apps/ellc/geometry_command.cpp).

#include <cstdint>

#include "ellc/cases/poses_file.hpp"
#include "ellc/contact/normal_contact.hpp"
#include "ellc/io/input_error.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace ellc;
  try {
    const PosesCase poses = parse_poses(fuzz::text_of(data, size), "fuzz_poses.toml");
    const PosesContact found = find_contact(poses);
    const NarrowPhaseResult& result = found.result;
    if (result.status != NarrowPhaseStatus::contact) return 0;
    const NormalContact contact = normal_contact(result.geometry, found.material, found.mean_radius_sum,
                                                 poses.model.hertz, poses.model.law, poses.max_overlap);
    (void)contact;
  } catch (const InputError&) {
  }
  return 0;
}
