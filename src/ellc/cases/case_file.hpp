#pragma once
// The two-body case file shared by `ellc curve`, `ellc geometry` and the FE pipeline:
// [material], [body_I], [body_J] (each may carry its own [body_X.material]), [protocol], [model].

#include <Eigen/Core>

#include <cstddef>
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

// A key of [model] on which two model specs differ, with both values as text (the keys and their
// order are read_model's).
struct ModelDifference {
  std::string key;
  std::string first;
  std::string second;
};
[[nodiscard]] std::vector<ModelDifference> model_differences(const ModelSpec& first, const ModelSpec& second);

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

// Bounds of the number format for the two-body tools (docs/geometry.md §10). Every length that
// places or shapes a body (semi-axes, mean_radius, positions, the wall's point) lies within
// [−kMaxLength, kMaxLength], semi-axes in [kMinLength, kMaxLength]: then squares and inverse
// squares of lengths (≤ 1e100), curvatures a/c² (≤ 1e150), their products in eq. (5) (≤ 1e300)
// and squared centre distances stay finite. Overlaps are bounded by the bodies themselves (an
// overlap beyond a_I + a_J has the centres passed through each other).
inline constexpr double kMaxLength = 1e50;
inline constexpr double kMinLength = 1e-50;
inline constexpr long kMaxPointsPerSegment = 1'000'000;
inline constexpr std::size_t kMaxCurvePoints = 10'000'000;

// "[x, y, z]" in the short number form of messages.
[[nodiscard]] std::string format_vector(const Eigen::Vector3d& vector);

// The input fields a two-body result depends on, for tracing a non-finite or invalid derived
// quantity back to what the user wrote (e.g. "[material] / [body_I.material]").
struct TwoBodyFields {
  std::string source;    // file name
  std::string shape;     // e.g. "body_I.semi_axes = [..], body_J.semi_axes = [..]"
  std::string material;  // e.g. "material.youngs_modulus = .., material.yield_stress = .."
};
[[nodiscard]] TwoBodyFields two_body_fields(const std::string& source, const BodySpec& body_i,
                                            const std::string& name_i, const BodySpec& body_j,
                                            const std::string& name_j);
// Empty when the constants are valid; otherwise a sentence that names the input fields the bad
// quantity comes from (the shape for R_e, e, f1, f2; the material for E_e, Y; both for δ_Y;
// [model] for λ_max, ε_max), then the derived quantity and its value.
[[nodiscard]] std::string traced_constants_error(const ContactConstants& constants, const TwoBodyFields& fields);

// The calibrated range of the transition fits (paper Table 2): b/a and c/a in [0.5, 2].
inline constexpr double kCalibratedAspectMin = 0.5;
inline constexpr double kCalibratedAspectMax = 2.0;

}  // namespace ellc
