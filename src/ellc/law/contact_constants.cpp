#include "ellc/law/contact_constants.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

namespace ellc {

ContactConstants make_yield_constants(const ContactMaterial& material, const HertzShape& shape,
                                      const LawParameters& parameters) noexcept {
  constexpr double pi = std::numbers::pi;
  ContactConstants c;
  c.effective_modulus = material.effective_modulus;
  c.yield_stress = material.yield_stress;
  c.equivalent_radius = shape.equivalent_radius;
  c.eccentricity_sq = shape.eccentricity_sq;
  c.f1 = shape.f1;
  c.f2 = shape.f2;
  c.contact_radius_sq_per_overlap = shape.contact_radius_sq_per_overlap();
  c.hertz_coefficient = (4.0 / 3.0) * c.effective_modulus * std::sqrt(c.equivalent_radius) / (c.f2 * std::sqrt(c.f2));
  c.yield_pressure_factor = parameters.yield_pressure_factor;
  c.yield_pressure = parameters.yield_pressure_factor * c.yield_stress;
  c.yield_contact_radius =
      c.yield_pressure * pi * c.equivalent_radius * c.f1 * c.f1 * c.f1 / (2.0 * c.effective_modulus);
  const double yield_radius_sq = c.yield_contact_radius * c.yield_contact_radius;
  c.yield_overlap = yield_radius_sq / c.contact_radius_sq_per_overlap;
  c.yield_force = (2.0 / 3.0) * pi * yield_radius_sq * c.yield_pressure;
  c.transition_exponent = parameters.fit.transition_exponent;
  constexpr double unset = std::numeric_limits<double>::quiet_NaN();  // set_transition_constants
  c.lambda_max = c.epsilon_max = c.plastic_limit_overlap = unset;
  return c;
}

void set_transition_constants(ContactConstants& c, double mean_radius_sum, const LawParameters& parameters) noexcept {
  const double radius_ratio = c.equivalent_radius / mean_radius_sum;    // R_e / r̂^{I,J}
  const double stiffness_ratio = c.effective_modulus / c.yield_stress;  // η = E_e/Y
  c.lambda_max = parameters.fit.lambda_max_for(radius_ratio, stiffness_ratio);
  c.epsilon_max = parameters.fit.epsilon_max_for(radius_ratio, stiffness_ratio);
  c.plastic_limit_overlap = c.epsilon_max * c.epsilon_max * c.yield_overlap;
}

ContactConstants make_contact_constants(const ContactMaterial& material, const HertzShape& shape,
                                        double mean_radius_sum, const LawParameters& parameters) noexcept {
  ContactConstants c = make_yield_constants(material, shape, parameters);
  set_transition_constants(c, mean_radius_sum, parameters);
  return c;
}

ContactConstants make_contact_constants(const ContactMaterial& material, PrincipalCurvatures body_i,
                                        PrincipalCurvatures body_j, double alpha, double mean_radius_sum,
                                        HertzMode mode, const LawParameters& parameters) noexcept {
  const HertzShape shape = hertz_shape(relative_curvature(body_i, body_j, alpha), mode);
  return make_contact_constants(material, shape, mean_radius_sum, parameters);
}

HertzShape hertz_shape_of(const ContactConstants& c) noexcept {
  return {c.equivalent_radius, c.eccentricity_sq, c.f1, c.f2};
}

std::string validation_error(const ContactConstants& c) {
  std::ostringstream out;
  out.precision(17);
  const struct {
    const char* name;
    double value;
  } positive[] = {{"effective modulus E_e", c.effective_modulus},
                  {"yield stress Y", c.yield_stress},
                  {"effective radius R_e", c.equivalent_radius},
                  {"correction factor f1", c.f1},
                  {"correction factor f2", c.f2},
                  {"yield overlap delta_Y", c.yield_overlap}};
  for (const auto& [name, value] : positive) {
    if (!std::isfinite(value) || value <= 0.0) {
      out << name << " = " << value << ": expected a finite number > 0";
      return out.str();
    }
  }
  if (!std::isfinite(c.lambda_max) || c.lambda_max < c.yield_pressure_factor)
    out << "lambda_max = " << c.lambda_max
        << " (from the [model] fit m, o, p and its form): expected a finite number >= " << c.yield_pressure_factor
        << " (the pressure cannot fall after first yield)";
  else if (!std::isfinite(c.epsilon_max) || c.epsilon_max < 1.0)
    out << "epsilon_max = " << c.epsilon_max << " (from the [model] fit s, t, u): expected a finite number >= 1";
  return out.str();
}

}  // namespace ellc
