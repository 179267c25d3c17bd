#include "ellc/geometry/tip_contact.hpp"

#include <cmath>

namespace ellc {

double mean_radius(const Eigen::Vector3d& semi_axes) noexcept { return std::cbrt(semi_axes.prod()); }

PrincipalCurvatures tip_curvatures(const Eigen::Vector3d& semi_axes) noexcept {
  const double a = semi_axes.x();
  return {a / (semi_axes.y() * semi_axes.y()), a / (semi_axes.z() * semi_axes.z())};
}

TipContact tip_contact(const TipBody& body_i, const TipBody& body_j) noexcept {
  // Both κ1 directions are the bodies' y axes rotated about the common x axis by their twists,
  // so the angle between them is the difference of the twists.
  return {tip_curvatures(body_i.semi_axes), tip_curvatures(body_j.semi_axes), body_i.twist - body_j.twist};
}

}  // namespace ellc
