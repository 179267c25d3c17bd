#pragma once
// The contact ellipse and pressure the law implies at a point of the history, for output and
// plots (paper Fig. 4, 9, 14): Hertz while elastic, Hertz truncated at p_λ = λY during plastic
// loading (eq. 12–25), Hertz with the radius R_e,pmax about δ_p while unloading (eq. 49).

#include <limits>

#include "ellc/hertz/elliptic_hertz.hpp"
#include "ellc/law/contact_law.hpp"

namespace ellc {

struct ContactPatch {
  double semi_axis_major = 0.0;                                   // a_c
  double semi_axis_minor = 0.0;                                   // b_c
  double field_peak_pressure = 0.0;                               // p0 of the elliptic (Hertz) field over the ellipse
  double pressure_cap = std::numeric_limits<double>::infinity();  // plateau p_λ; ∞ when elastic
  // Peak of the actual pressure: min(p0, cap).
  [[nodiscard]] double peak_pressure() const noexcept {
    return field_peak_pressure < pressure_cap ? field_peak_pressure : pressure_cap;
  }
};

[[nodiscard]] inline ContactPatch contact_patch(const ContactConstants& c, double overlap,
                                                double max_overlap) noexcept {
  ContactPatch patch;
  const LawResult result = evaluate_contact(c, overlap, max_overlap);
  HertzShape shape = hertz_shape_of(c);
  double elastic_overlap = overlap;
  if (result.regime == Regime::unloading) {
    const UnloadingBranch branch = unloading_branch(c, max_overlap);
    shape.equivalent_radius = branch.unloading_radius;
    elastic_overlap = overlap - branch.plastic_overlap;
  } else if (result.regime == Regime::separated) {
    return patch;
  }
  const HertzContact hertz = hertz_contact(shape, c.effective_modulus, elastic_overlap);
  patch.semi_axis_major = hertz.semi_axis_major;
  patch.semi_axis_minor = hertz.semi_axis_minor;
  patch.field_peak_pressure = hertz.peak_pressure;
  if (result.regime == Regime::elastic_plastic)
    patch.pressure_cap = transition_lambda(c, hertz.equivalent_contact_radius) * c.yield_stress;
  else if (result.regime == Regime::fully_plastic)
    patch.pressure_cap = c.lambda_max * c.yield_stress;
  return patch;
}

}  // namespace ellc
