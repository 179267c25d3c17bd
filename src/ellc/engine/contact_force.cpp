#include "ellc/engine/contact_force.hpp"

#include <algorithm>
#include <cmath>

#include "ellc/response/normal_damping.hpp"
#include "ellc/response/tangential_spring.hpp"

namespace ellc::engine {

Eigen::Vector3d contact_response(const ContactKinematics& kinematics, const ContactConstants& constants,
                                 double overlap, double law_force, const ResponseParameters& parameters,
                                 ContactHistory& history) noexcept {
  const Eigen::Vector3d& n = kinematics.normal;
  // The engine's parametrisation; the damping and friction algorithms are src/ellc/response's.
  const double contact_radius = std::sqrt(constants.contact_radius_sq_per_overlap * std::max(overlap, 0.0));
  const double normal_speed = kinematics.relative_velocity.dot(n);  // > 0 when separating
  const double normal_stiffness = 2.0 * constants.effective_modulus * contact_radius;
  const double normal_force = damped_normal_force(
      law_force, viscous_damping(parameters.damping_ratio, kinematics.effective_mass, normal_stiffness), normal_speed);

  const double tangential_stiffness = 8.0 * parameters.shear_modulus * contact_radius;  // Mindlin
  const TangentialCoefficients tangential{
      tangential_stiffness, viscous_damping(parameters.damping_ratio, kinematics.effective_mass, tangential_stiffness),
      parameters.friction};
  const TangentialResponse friction = tangential_response(history.tangential_spring, n, kinematics.relative_velocity,
                                                          parameters.dt, normal_force, tangential);
  history.tangential_spring = friction.spring;
  return normal_force * n + friction.force;
}

double recoverable_energy(const ContactConstants& constants, double overlap, double max_overlap) noexcept {
  if (!(overlap > 0.0)) return 0.0;
  // ∫₀^x C s^{3/2} ds = (2/5) C x^{5/2} for the branch F = C x^{3/2}.
  const auto energy = [](double coefficient, double x) { return x > 0.0 ? 0.4 * coefficient * x * x * std::sqrt(x) : 0.0; };
  if (max_overlap <= constants.yield_overlap) return energy(constants.hertz_coefficient, overlap);
  const UnloadingBranch branch = unloading_branch(constants, std::max(max_overlap, overlap));
  return energy(branch.unloading_coefficient, overlap - branch.plastic_overlap);
}

namespace {
// Simpson's rule for the loading force over [a, b] (exact for the linear fully plastic branch).
double loading_work(const ContactConstants& c, double a, double b) noexcept {
  if (!(b > a)) return 0.0;
  constexpr int intervals = 32;
  const double h = (b - a) / intervals;
  double sum = loading_force(c, a).force + loading_force(c, b).force;
  for (int k = 1; k < intervals; ++k) sum += (k % 2 == 1 ? 4.0 : 2.0) * loading_force(c, a + k * h).force;
  return sum * h / 3.0;
}
}  // namespace

double plastic_work(const ContactConstants& c, double max_overlap) noexcept {
  if (!(max_overlap > c.yield_overlap)) return 0.0;
  const double yield = c.yield_overlap;
  const double hertz = 0.4 * c.hertz_coefficient * yield * yield * std::sqrt(yield);
  const double transition_end = std::min(max_overlap, c.plastic_limit_overlap);
  const double loading = hertz + loading_work(c, yield, transition_end) + loading_work(c, transition_end, max_overlap);
  return loading - recoverable_energy(c, max_overlap, max_overlap);
}

double clear_history(ContactHistory& history) noexcept {
  const double released = plastic_work(history.constants, history.max_overlap);
  const bool keep_constants = history.constants_cached;
  const ContactConstants constants = history.constants;
  const WarmStart axis = history.warm_start;
  history = ContactHistory{};
  history.constants_cached = keep_constants;  // sphere pairs: the constants do not change
  history.constants = constants;
  history.warm_start = axis;  // the separating axis just found warm-starts the next test
  return released;
}

}  // namespace ellc::engine
