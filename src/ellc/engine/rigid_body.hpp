#pragma once
// Rigid-body kinematics for the velocity-Verlet integrator: Euler's equations in the body frame
// and the quaternion update for a body-frame angular velocity.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>

namespace ellc::engine {

// Principal moments of inertia of a solid ellipsoid of mass m and semi-axes (a, b, c), body frame.
[[nodiscard]] inline Eigen::Vector3d solid_ellipsoid_inertia(double mass, const Eigen::Vector3d& semi_axes) noexcept {
  const Eigen::Vector3d sq = semi_axes.cwiseProduct(semi_axes);
  return {mass * (sq.y() + sq.z()) / 5.0, mass * (sq.x() + sq.z()) / 5.0, mass * (sq.x() + sq.y()) / 5.0};
}

// ω = R I⁻¹ Rᵀ L: the world-frame angular velocity of a body with world-frame angular momentum L.
[[nodiscard]] inline Eigen::Vector3d angular_velocity_from_momentum(const Eigen::Vector3d& angular_momentum,
                                                                    const Eigen::Quaterniond& orientation,
                                                                    const Eigen::Vector3d& inertia) noexcept {
  return orientation * (orientation.conjugate() * angular_momentum).cwiseQuotient(inertia);
}

// dω/dt = I⁻¹ (τ − ω × I ω), all in the body frame (Euler's equations).
[[nodiscard]] inline Eigen::Vector3d angular_acceleration(const Eigen::Vector3d& inertia, const Eigen::Vector3d& omega,
                                                          const Eigen::Vector3d& torque_body) noexcept {
  return (torque_body - omega.cross(inertia.cwiseProduct(omega))).cwiseQuotient(inertia);
}

// q ← q ⊗ exp(ω dt / 2): rotation by the body-frame angular velocity ω over dt, renormalised.
[[nodiscard]] inline Eigen::Quaterniond advance_orientation(const Eigen::Quaterniond& q, const Eigen::Vector3d& omega,
                                                            double dt) noexcept {
  const double rate = omega.norm();
  const double half_angle = 0.5 * rate * dt;
  // cos(θ/2) and sin(θ/2)/|ω| = (dt/2) sin(θ/2)/(θ/2). A DEM step turns a body by far less than
  // 0.02 rad, where the Taylor series below are exact to rounding (the first omitted terms are
  // below 10⁻²⁷) and cost a fraction of std::sin and std::cos, with no division by |ω| ~ 0.
  double cosine = 0.0;
  double scale = 0.0;
  if (half_angle < 0.01) {
    const double h2 = half_angle * half_angle;
    cosine = 1.0 - h2 * (1.0 / 2.0 - h2 * (1.0 / 24.0 - h2 * (1.0 / 720.0 - h2 * (1.0 / 40320.0))));
    scale = 0.5 * dt * (1.0 - h2 * (1.0 / 6.0 - h2 * (1.0 / 120.0 - h2 * (1.0 / 5040.0 - h2 * (1.0 / 362880.0)))));
  } else {
    cosine = std::cos(half_angle);
    scale = std::sin(half_angle) / rate;
  }
  const Eigen::Quaterniond step(cosine, scale * omega.x(), scale * omega.y(), scale * omega.z());
  return (q * step).normalized();
}

}  // namespace ellc::engine
