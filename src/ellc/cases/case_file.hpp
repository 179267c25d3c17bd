#pragma once
// The two-body case file shared by `ellc curve`, `ellc geometry` and the FE pipeline:
// [material], [body_I], [body_J] (each may carry its own [body_X.material]), [protocol], [model].

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

#include "ellc/hertz/elliptic_hertz.hpp"
#include "ellc/io/table_reader.hpp"
#include "ellc/law/contact_constants.hpp"
#include "ellc/law/transition_fit.hpp"
#include "ellc/material/material.hpp"

namespace ellc {

struct BodySpec {
  Eigen::Vector3d semi_axes{1.0, 1.0, 1.0};  // (a, b, c), a along x
  double twist = 0.0;                        // radians about x
  Material material;
};

struct ModelSpec {
  HertzMode hertz = HertzMode::hale;
  LawParameters law;
};

struct CurveCase {
  BodySpec body_i;
  BodySpec body_j;
  std::vector<double> waypoints;  // absolute overlaps
  long points_per_segment = 50;
  ModelSpec model;
  std::vector<std::string> warnings;  // e.g. aspect ratios outside the calibrated range
};

// Readers for the pieces, reusable by other input files.
[[nodiscard]] Material read_material(TableReader& table);
// semi_axes = [a, b, c]  or  aspect = [1, b/a, c/a] with mean_radius; `twist_deg` optional.
// Warnings go to `warnings`. `default_material` fills in when the body has no [material] table.
[[nodiscard]] BodySpec read_body(TableReader& table, const std::optional<Material>& default_material,
                                 std::vector<std::string>& warnings);
[[nodiscard]] ModelSpec read_model(TableReader& table);

// [material] (optional when each body has its own), [body_I] and [body_J] of a case's root table.
struct BodyPair {
  BodySpec body_i;
  BodySpec body_j;
};
[[nodiscard]] BodyPair read_body_pair(TableReader& root, std::vector<std::string>& warnings);

// Reads and validates a whole case; throws InputError on the first problem.
[[nodiscard]] CurveCase read_curve_case(const std::string& path);
[[nodiscard]] CurveCase parse_curve_case(std::string_view toml_text, const std::string& source);

// Contact constants of the two bodies of a case touching tip to tip (paper Sec. 5): curvatures
// from tip_contact(), E_e and Y mixed from the bodies' materials, r̂^{I,J} = r̂^I + r̂^J.
[[nodiscard]] ContactConstants case_contact_constants(const BodySpec& body_i, const BodySpec& body_j, HertzMode mode,
                                                      const LawParameters& law);

// The calibrated range of the transition fits (paper Table 2): b/a and c/a in [0.5, 2].
inline constexpr double kCalibratedAspectMin = 0.5;
inline constexpr double kCalibratedAspectMax = 2.0;

}  // namespace ellc
