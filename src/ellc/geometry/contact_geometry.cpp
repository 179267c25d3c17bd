#include "ellc/geometry/contact_geometry.hpp"

#include <cmath>
#include <numbers>

namespace ellc {

namespace {

// Gives `side` the principal directions of `partner`, projected on the tangent plane of the
// outward normal `outward`; keeps its own if the projection degenerates.
void adopt_directions(SurfaceCurvature& side, const SurfaceCurvature& partner,
                      const Eigen::Vector3d& outward) noexcept {
  const Eigen::Vector3d projected = partner.direction_1 - partner.direction_1.dot(outward) * outward;
  const double length = projected.norm();
  if (!(length > 1e-12)) return;
  side.direction_1 = projected / length;
  side.direction_2 = outward.cross(side.direction_1);
}

}  // namespace

void pair_principal_directions(ContactGeometry& geometry, const Eigen::Vector3d& normal) noexcept {
  SurfaceCurvature& side_i = geometry.curvature_i;
  SurfaceCurvature& side_j = geometry.curvature_j;
  geometry.alpha = 0.0;
  if (side_i.umbilic()) {
    adopt_directions(side_i, side_j, normal);
    return;
  }
  if (side_j.umbilic()) {
    adopt_directions(side_j, side_i, -normal);
    return;
  }
  const double cosine = std::abs(side_i.direction_1.dot(side_j.direction_1));
  const double sine = side_i.direction_1.cross(side_j.direction_1).norm();
  if (cosine == 0.0 && sine == 0.0) return;  // degenerate directions: α = 0
  // atan2(sine, cosine) for sine, cosine ≥ 0, via atan on a ratio ≤ 1 (cheaper than atan2).
  geometry.alpha = sine <= cosine ? std::atan(sine / cosine) : 0.5 * std::numbers::pi - std::atan(cosine / sine);
}

}  // namespace ellc
