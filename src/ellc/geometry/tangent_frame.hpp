#pragma once
// Small fixed-size helpers shared by the ellipsoid and the narrow phase: an orthonormal tangent
// frame for a unit normal, and the eigen-decomposition of a symmetric 2×2 matrix. Header-only,
// noexcept, no allocation.

#include <Eigen/Core>

#include <cmath>

namespace ellc::geometry_detail {

// Two unit tangents with (t1, t2, n) right-handed, for a unit n. Branch on the sign of n_z only,
// so it is finite everywhere (Duff et al. 2017, "Building an orthonormal basis, revisited",
// J. Computer Graphics Techniques 6(1)).
struct TangentFrame {
  Eigen::Vector3d t1;
  Eigen::Vector3d t2;
};

[[nodiscard]] inline TangentFrame tangent_frame(const Eigen::Vector3d& n) noexcept {
  const double sign = std::copysign(1.0, n.z());
  const double a = -1.0 / (sign + n.z());
  const double b = n.x() * n.y() * a;
  return {Eigen::Vector3d(1.0 + sign * n.x() * n.x() * a, sign * b, -sign * n.x()),
          Eigen::Vector3d(b, sign + n.y() * n.y() * a, -n.y())};
}

// Symmetric [[s11, s12], [s12, s22]]: eigenvalues high ≥ low and the unit eigenvector (x, y) of
// `high`. When the two eigenvalues coincide to `umbilic_tolerance` (relative), the eigenvector is
// (1, 0): any direction is an eigenvector then, and this keeps the choice deterministic.
struct SymmetricEigen2 {
  double high;
  double low;
  double x;
  double y;
};

[[nodiscard]] inline SymmetricEigen2 symmetric_eigen2(double s11, double s12, double s22,
                                                      double umbilic_tolerance) noexcept {
  const double mean = 0.5 * (s11 + s22);
  const double half_difference = 0.5 * (s11 - s22);
  const double radius = std::sqrt(half_difference * half_difference + s12 * s12);
  SymmetricEigen2 result{mean + radius, mean - radius, 1.0, 0.0};
  if (2.0 * radius <= umbilic_tolerance * (std::abs(s11) + std::abs(s22))) return result;
  // Two expressions for the same eigenvector; take the one without cancellation.
  double x = half_difference + radius;
  double y = s12;
  if (half_difference < 0.0) {
    x = s12;
    y = radius - half_difference;
  }
  const double length = std::sqrt(x * x + y * y);
  result.x = x / length;
  result.y = y / length;
  return result;
}

}  // namespace ellc::geometry_detail
