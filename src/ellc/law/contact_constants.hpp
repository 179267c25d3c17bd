#pragma once
// Everything about one contact that does not depend on the overlap: the Hertz shape, the yield
// point and the transition parameters (docs/model.md §2–3). Built once per contact configuration
// (or per step in a DEM where the curvatures move); the law then needs only δ and δ_*.

#include <string>

#include "ellc/hertz/elliptic_hertz.hpp"
#include "ellc/law/transition_fit.hpp"
#include "ellc/material/material.hpp"

namespace ellc {

struct ContactConstants {
  double effective_modulus = 0.0;              // E_e, eq. (3)
  double yield_stress = 0.0;                   // Y
  double equivalent_radius = 0.0;              // R_e, eq. (6)
  double eccentricity_sq = 0.0;                // e², eq. (7)
  double f1 = 1.0;                             // eq. (4)
  double f2 = 1.0;                             // eq. (4)
  double contact_radius_sq_per_overlap = 0.0;  // c_c²/δ = R_e f1²/f2, eq. (9)
  double hertz_coefficient = 0.0;              // F_H/δ^{3/2} = (4/3) E_e sqrt(R_e) f2^{-3/2}, eq. (10)
  double yield_pressure = 0.0;                 // p_Y = 1.6 Y
  double yield_contact_radius = 0.0;           // c_Y = p_Y π R_e f1³ / (2 E_e), from eq. (2)
  double yield_overlap = 0.0;                  // δ_Y = c_Y² f2 / (R_e f1²), eq. (9)
  double yield_force = 0.0;                    // F_pY = (2/3) π c_Y² p_Y
  double lambda_max = 0.0;                     // eq. (52), or its stiffness_ratio form (transition_fit.hpp)
  double epsilon_max = 0.0;                    // eq. (52), likewise
  double transition_exponent = 0.0;            // n, eq. (28)
  double yield_pressure_factor = 1.6;          // λ at first yield
  double plastic_limit_overlap = 0.0;          // δ_max = ε_max² δ_Y, eq. (30)
};

// `mean_radius_sum` is r̂^{I,J} = r̂^I + r̂^J of eq. (50).
[[nodiscard]] ContactConstants make_contact_constants(const ContactMaterial& material, const HertzShape& shape,
                                                      double mean_radius_sum,
                                                      const LawParameters& parameters = {}) noexcept;

// make_contact_constants in its two stages, for a caller that builds constants per contact and
// step (a DEM). First everything the law reads up to first yield (E_e, R_e, f1, f2, the Hertz
// coefficient, the yield point, n); λ_max, ε_max and δ_max, which the law reads only beyond δ_Y
// (law_needs_transition, contact_law.hpp), are NaN. Then the transition fit (eq. 52, two exp)
// sets those three. Both stages together are make_contact_constants, bit for bit.
[[nodiscard]] ContactConstants make_yield_constants(const ContactMaterial& material, const HertzShape& shape,
                                                    const LawParameters& parameters = {}) noexcept;
void set_transition_constants(ContactConstants& constants, double mean_radius_sum,
                              const LawParameters& parameters = {}) noexcept;

// The usual path: principal curvatures of both bodies and the angle α between their κ1
// directions → A, B (eq. 5) → Hertz shape → constants.
[[nodiscard]] ContactConstants make_contact_constants(const ContactMaterial& material, PrincipalCurvatures body_i,
                                                      PrincipalCurvatures body_j, double alpha, double mean_radius_sum,
                                                      HertzMode mode, const LawParameters& parameters = {}) noexcept;

// The Hertz shape the constants were built from (R_e, e², f1, f2).
[[nodiscard]] HertzShape hertz_shape_of(const ContactConstants& constants) noexcept;

// Empty when the law can be evaluated with these constants (finite, positive, λ_max ≥ 1.6 Y-factor,
// ε_max ≥ 1); otherwise a sentence naming the quantity and its value.
[[nodiscard]] std::string validation_error(const ContactConstants& constants);

}  // namespace ellc
