#include "ellc/engine/time_step.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace ellc::engine {

double rayleigh_time(double radius, double density, const Material& material) noexcept {
  const double shear_modulus = material.youngs_modulus / (2.0 * (1.0 + material.poisson_ratio));
  return std::numbers::pi * radius * std::sqrt(density / shear_modulus) / (0.1631 * material.poisson_ratio + 0.8766);
}

double stable_time_step(const ParticleSet& particles, double density, const Material& material,
                        double safety) noexcept {
  double smallest = std::numeric_limits<double>::infinity();
  for (const auto& axes : particles.semi_axes) smallest = std::min(smallest, axes.minCoeff());
  return safety * rayleigh_time(smallest, density, material);
}

}  // namespace ellc::engine
