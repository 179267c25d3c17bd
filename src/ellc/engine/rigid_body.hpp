#pragma once
// Rigid-body kinematics for the velocity-Verlet integrator: Euler's equations in the body frame
// and the quaternion update for a body-frame angular velocity.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>

namespace ellc::engine {

// dω/dt = I⁻¹ (τ − ω × I ω), all in the body frame (Euler's equations).
[[nodiscard]] inline Eigen::Vector3d angular_acceleration(const Eigen::Vector3d& inertia,
                                                          const Eigen::Vector3d& omega,
                                                          const Eigen::Vector3d& torque_body) noexcept {
  return (torque_body - omega.cross(inertia.cwiseProduct(omega))).cwiseQuotient(inertia);
}

// q ← q ⊗ exp(ω dt / 2): rotation by the body-frame angular velocity ω over dt, renormalised.
[[nodiscard]] inline Eigen::Quaterniond advance_orientation(const Eigen::Quaterniond& q, const Eigen::Vector3d& omega,
                                                            double dt) noexcept {
  const double rate = omega.norm();
  const double half_angle = 0.5 * rate * dt;
  // sin(θ/2)/|ω|, with its series where |ω| dt is tiny (no division by ~0).
  const double scale = half_angle < 1e-6 ? 0.5 * dt * (1.0 - half_angle * half_angle / 6.0)
                                         : std::sin(half_angle) / rate;
  const Eigen::Quaterniond step(std::cos(half_angle), scale * omega.x(), scale * omega.y(), scale * omega.z());
  return (q * step).normalized();
}

}  // namespace ellc::engine
