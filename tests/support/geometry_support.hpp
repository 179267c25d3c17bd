#pragma once
// Random poses and pair placement shared by the geometry tests.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>
#include <random>

#include "ellc/geometry/ellipsoid.hpp"

namespace ellc::test {

using Rng = std::mt19937_64;

inline Eigen::Quaterniond random_orientation(Rng& rng) {
  std::normal_distribution<double> gauss;
  Eigen::Quaterniond q(gauss(rng), gauss(rng), gauss(rng), gauss(rng));
  q.normalize();
  return q;
}

inline Eigen::Vector3d random_unit(Rng& rng) {
  std::normal_distribution<double> gauss;
  Eigen::Vector3d v(gauss(rng), gauss(rng), gauss(rng));
  return v.normalized();
}

inline double uniform(Rng& rng, double low, double high) {
  return std::uniform_real_distribution<double>(low, high)(rng);
}

// Semi-axes with aspect 1 : [0.3..3] : [0.3..3] (log-uniform) scaled to mean radius r̂.
inline Eigen::Vector3d random_semi_axes(Rng& rng, double mean_radius) {
  const Eigen::Vector3d aspect(1.0, std::exp(uniform(rng, std::log(0.3), std::log(3.0))),
                               std::exp(uniform(rng, std::log(0.3), std::log(3.0))));
  return aspect * (mean_radius / std::cbrt(aspect.prod()));
}

// Places J so that unit n is a common normal of I and J with overlap δ:
// c_J = c_I + (p_I(n) − c_I) + (c_J − p_J(n)) − δ n.
inline Ellipsoid place_partner(const Ellipsoid& body_i, const Eigen::Vector3d& semi_axes_j,
                               const Eigen::Quaterniond& orientation_j, const Eigen::Vector3d& n, double overlap) {
  const Ellipsoid at_origin(semi_axes_j, {Eigen::Vector3d::Zero(), orientation_j});
  const Eigen::Vector3d arm_i = body_i.support_point(n) - body_i.center();
  const Eigen::Vector3d arm_j = -at_origin.support_point(-n);
  return Ellipsoid(semi_axes_j, {body_i.center() + arm_i + arm_j - overlap * n, orientation_j});
}

// Rotation taking body axis `axis` (0, 1, 2) of an identity-oriented body onto world `direction`.
inline Eigen::Quaterniond align_axis(int axis, const Eigen::Vector3d& direction) {
  return Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::Unit(axis), direction);
}

inline double relative_difference(double a, double b) {
  const double scale = std::max(std::abs(a), std::abs(b));
  return scale == 0.0 ? 0.0 : std::abs(a - b) / scale;
}

}  // namespace ellc::test
