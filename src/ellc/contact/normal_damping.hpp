#pragma once
// Viscous damping of a contact and the damped normal force, used by contact_force()
// (contact_force.hpp), which both engines run. The stiffness comes from the damping sub-model
// (contact_model.hpp: k_n = 2 E_e c, or the Hertz tangent 3/2 C x^{1/2}); the formulas below exist
// only here. Header-only, noexcept, no allocation.

#include <algorithm>
#include <cmath>

namespace ellc {

// c = 2 ζ sqrt(m* k): the fraction ζ of the critical damping of a mass m* on a spring k, so that
// ζ means the same for every stiffness and mass. ζ = 0 returns 0 without the square root (the
// same 0 as the formula for any finite m* k ≥ 0; the undamped models of both engines run so).
[[nodiscard]] inline double viscous_damping(double damping_ratio, double effective_mass, double stiffness) noexcept {
  if (damping_ratio == 0.0) return 0.0;
  return 2.0 * damping_ratio * std::sqrt(effective_mass * stiffness);
}

// F_n = max(0, F_law − c_n v_n), v_n > 0 when the bodies separate. The clamp keeps the dashpot
// from pulling the bodies together: a contact pushes or carries nothing.
[[nodiscard]] inline double damped_normal_force(double law_force, double normal_damping, double normal_speed) noexcept {
  return std::max(0.0, law_force - normal_damping * normal_speed);
}

}  // namespace ellc
