#pragma once
// From contact geometry straight to the normal force: the relative curvature A, B of the geometry
// (eq. 5) goes through make_contact_constants (eq. 6–10, 50–54) and evaluate_contact (the
// Becker–Kamlah law) unchanged, so a tip-to-tip geometry gives the numbers of `ellc curve` (to
// the rounding of the geometry).

#include <Eigen/Core>

#include "ellc/geometry/contact_geometry.hpp"
#include "ellc/hertz/elliptic_hertz.hpp"
#include "ellc/law/contact_constants.hpp"
#include "ellc/law/contact_law.hpp"
#include "ellc/material/material.hpp"

namespace ellc {

struct NormalContact {
  Eigen::Vector3d force_on_j = Eigen::Vector3d::Zero();         // F n: pushes J away from I
  Eigen::Vector3d application_point = Eigen::Vector3d::Zero();  // the contact point
  LawResult law;                                                // force magnitude, new δ_*, regime
  ElasticBranch branch;                                         // the curve the law was on
  ContactConstants constants;                                   // of this configuration
};

// What NormalContact::constants holds. `all`: every constant of the configuration. `law_reads`:
// what the law read at this δ and δ_* (the DEM engines, which rebuild the constants every step and
// read them back only as the law does: energies of yielded contacts, c_c/r̂): Hale's e² is NaN,
// and so are λ_max, ε_max and δ_max while δ and δ_* are at most δ_Y (law_needs_transition). The
// force, the branch and every constant that is set are the same bits either way; it saves one
// exp (e²) per contact, and two more (eq. 52) per contact that never yielded.
enum class ConstantsScope { all, law_reads };

// `mean_radius_sum` = r̂^I + r̂^J (eq. 50); for a wall use wall_mean_radius_sum(). `max_overlap` is
// the contact's δ_* before this step (0 for a fresh contact); store law.max_overlap afterwards.
// A geometry with overlap ≤ 0 gives zero force (regime separated).
[[nodiscard]] NormalContact normal_contact(const ContactGeometry& geometry, const ContactMaterial& material,
                                           double mean_radius_sum, HertzMode mode, const LawParameters& parameters,
                                           double max_overlap, ConstantsScope scope = ConstantsScope::all) noexcept;

}  // namespace ellc
