#pragma once
// Coulomb friction with a tangential history spring (Cundall & Strack 1979), used by
// contact_force() (contact_force.hpp), which both engines run. k_t and c_t come from the
// tangential sub-model (contact_model.hpp: Mindlin k_t = 8 G_e c, or k_t = κ k_n); the algorithm
// exists only here.
//
// One step, with n the unit normal I → J and v the velocity of J relative to I at the contact:
//   1. ξ is carried onto the current tangent plane, its length kept (the contact plane turns
//      with the bodies, the stored elastic displacement does not change);
//   2. ξ += v_t dt, v_t = v − (v·n) n;
//   3. F_t = −k_t ξ − c_t v_t;
//   4. if |F_t| > μ F_n the contact slides: F_t is scaled to μ F_n and ξ reset to
//      −(F_t + c_t v_t)/k_t, the spring that gives exactly that force.
// Without friction (μ ≤ 0) or spring (k_t ≤ 0) there is no tangential force and ξ stays zero.
// Header-only, noexcept, no allocation.

#include <Eigen/Core>

#include <cmath>

namespace ellc {

struct TangentialCoefficients {
  double stiffness = 0.0;  // k_t
  double damping = 0.0;    // c_t
  double friction = 0.0;   // μ
};

struct TangentialResponse {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();   // F_t on J
  Eigen::Vector3d spring = Eigen::Vector3d::Zero();  // ξ after this step, tangential to n
  bool sliding = false;                              // |F_t| reached μ F_n; ξ was reset to it
};

// ξ without its component along the unit normal n, scaled back to its length. A spring exactly
// along n has no tangential direction left and becomes zero. One square root: the scale is
// sqrt(|ξ|²/|ξ_t|²), not |ξ|/|ξ_t| from two norms.
[[nodiscard]] inline Eigen::Vector3d carry_to_tangent_plane(const Eigen::Vector3d& spring,
                                                            const Eigen::Vector3d& normal) noexcept {
  const double length_sq = spring.squaredNorm();
  if (!(length_sq > 0.0)) return spring;  // nothing to turn (a non-finite ξ stays visible, not zeroed)
  const Eigen::Vector3d projected = spring - spring.dot(normal) * normal;
  const double projected_length_sq = projected.squaredNorm();
  return projected_length_sq > 0.0 ? Eigen::Vector3d(projected * std::sqrt(length_sq / projected_length_sq))
                                   : Eigen::Vector3d::Zero();
}

// One step of a spring ξ that already lies in the tangent plane of n (carry_to_tangent_plane; the
// contact model carries it once, before it rescales it for a changed k_t) under the normal force
// F_n ≥ 0 of this step: steps 2–4 above. Pure: the caller stores the returned spring.
[[nodiscard]] inline TangentialResponse tangential_response_on_plane(
    const Eigen::Vector3d& carried_spring, const Eigen::Vector3d& normal, const Eigen::Vector3d& relative_velocity,
    double dt, double normal_force, const TangentialCoefficients& coefficients) noexcept {
  TangentialResponse response;
  if (!(coefficients.friction > 0.0) || !(coefficients.stiffness > 0.0)) return response;
  const Eigen::Vector3d tangential_velocity = relative_velocity - relative_velocity.dot(normal) * normal;
  response.spring = carried_spring + tangential_velocity * dt;
  response.force = -coefficients.stiffness * response.spring - coefficients.damping * tangential_velocity;
  const double limit = coefficients.friction * normal_force;
  const double magnitude = response.force.norm();
  if (magnitude > limit) {
    response.force *= magnitude > 0.0 ? limit / magnitude : 0.0;  // 0 only if F_n < 0 was passed
    response.spring = -(response.force + coefficients.damping * tangential_velocity) / coefficients.stiffness;
    response.sliding = true;
  }
  return response;
}

// One step of the spring ξ (`spring`, as stored after the previous step): steps 1–4 above.
[[nodiscard]] inline TangentialResponse tangential_response(const Eigen::Vector3d& spring,
                                                            const Eigen::Vector3d& normal,
                                                            const Eigen::Vector3d& relative_velocity, double dt,
                                                            double normal_force,
                                                            const TangentialCoefficients& coefficients) noexcept {
  return tangential_response_on_plane(carry_to_tangent_plane(spring, normal), normal, relative_velocity, dt,
                                      normal_force, coefficients);
}

}  // namespace ellc
