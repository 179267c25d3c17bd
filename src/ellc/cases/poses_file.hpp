#pragma once
// The poses file of `ellc geometry`: two posed ellipsoids, or an ellipsoid and a wall.
//
// [material] (shared, optional if each body has its own), [body_I], and either [body_J] or
// [wall]; optional [model] and max_overlap (δ_* of the contact's history, default 0).
// A body is the table of the curve case (semi_axes or aspect + mean_radius, twist_deg, material)
// plus position = [x, y, z] and either orientation = [w, x, y, z] (unit quaternion, body → world)
// or axis = [x, y, z] with angle_deg. The twist about the body's own x axis is applied first.
// [wall]: point = [x, y, z], normal = [x, y, z] (into the particles' side), optional
// [wall.material] (default: the body's). Unknown keys are rejected.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ellc/cases/case_file.hpp"
#include "ellc/geometry/ellipsoid.hpp"
#include "ellc/geometry/narrow_phase.hpp"
#include "ellc/geometry/wall_contact.hpp"
#include "ellc/material/material.hpp"

namespace ellc {

// A body of a case file placed in the world. pose.orientation already includes spec.twist.
struct PosedBodySpec {
  BodySpec spec;
  Pose pose;
};

struct WallSpec {
  Plane plane;                       // unit normal, into the particles' side
  std::optional<Material> material;  // none: the body's
};

struct PosesCase {
  PosedBodySpec body_i;
  std::optional<PosedBodySpec> body_j;  // exactly one of body_j and wall is set
  std::optional<WallSpec> wall;
  ModelSpec model;
  double max_overlap = 0.0;           // δ_* of the contact's history (µm)
  std::vector<std::string> warnings;  // e.g. aspect ratios outside the calibrated range
};

// Reads and validates a poses file; throws InputError on the first problem.
[[nodiscard]] PosesCase read_poses(const std::string& path);
[[nodiscard]] PosesCase parse_poses(std::string_view toml_text, const std::string& source);

// What the law needs from a poses case: the narrow phase's answer for the pair (or the body and
// the wall), the mixed material, and the sum of mean radii that scales r̂ (a wall counts as
// the body's mirror image, wall_mean_radius_sum). `ellc geometry` and the poses fuzz target
// share it.
struct PosesContact {
  Ellipsoid body_i;
  NarrowPhaseResult result;
  ContactMaterial material;
  double mean_radius_sum = 0.0;
};
[[nodiscard]] PosesContact find_contact(const PosesCase& poses);

}  // namespace ellc
