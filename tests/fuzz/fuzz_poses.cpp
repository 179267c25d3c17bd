// Fuzz target: the poses file of `ellc geometry` (cases/poses_file.hpp). Bytes → TOML → validated
// PosesCase → the narrow phase (pair or wall) → the law at the overlap found. Crashes, sanitizer
// reports and hangs are findings here; whether `ellc geometry` prints finite numbers is its own
// check (apps/ellc/geometry_command.cpp).

#include <cstdint>

#include "ellc/cases/poses_file.hpp"
#include "ellc/contact/normal_contact.hpp"
#include "ellc/geometry/narrow_phase.hpp"
#include "ellc/geometry/wall_contact.hpp"
#include "ellc/io/input_error.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace ellc;
  try {
    const PosesCase poses = parse_poses(fuzz::text_of(data, size), "fuzz_poses.toml");
    const Ellipsoid body_i(poses.body_i.spec.semi_axes, poses.body_i.pose);
    NarrowPhaseResult result;
    ContactMaterial material;
    double mean_radius_sum = 0.0;
    if (poses.body_j) {
      const Ellipsoid body_j(poses.body_j->spec.semi_axes, poses.body_j->pose);
      result = ellipsoid_contact(body_i, body_j);
      material = mix(poses.body_i.spec.material, poses.body_j->spec.material);
      mean_radius_sum = body_i.mean_radius() + body_j.mean_radius();
    } else {
      result = wall_contact(body_i, poses.wall->plane);
      material = mix(poses.body_i.spec.material, poses.wall->material.value_or(poses.body_i.spec.material));
      mean_radius_sum = wall_mean_radius_sum(body_i);
    }
    if (result.status != NarrowPhaseStatus::contact) return 0;
    const NormalContact contact = normal_contact(result.geometry, material, mean_radius_sum, poses.model.hertz,
                                                 poses.model.law, poses.max_overlap);
    (void)contact;
  } catch (const InputError&) {
  }
  return 0;
}
