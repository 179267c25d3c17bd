#include "ellc/geometry/wall_contact.hpp"

#include <cmath>

namespace ellc {

NarrowPhaseResult wall_contact(const Ellipsoid& body, const Plane& wall) noexcept {
  NarrowPhaseResult result;
  const double normal_length = wall.normal.norm();
  if (!body.valid() || !wall.point.allFinite() || !std::isfinite(normal_length) || !(normal_length > 0.0))
    return result;
  const Eigen::Vector3d into_wall = -wall.normal / normal_length;  // from the body (I) to the wall (J)
  ContactGeometry& geometry = result.geometry;
  geometry.normal = into_wall;
  geometry.surface_point_i = body.support_point(into_wall);
  geometry.overlap = (geometry.surface_point_i - wall.point).dot(into_wall);
  geometry.surface_point_j = geometry.surface_point_i - geometry.overlap * into_wall;
  geometry.point = 0.5 * (geometry.surface_point_i + geometry.surface_point_j);
  result.warm_start = {{into_wall.x(), into_wall.y(), into_wall.z()}, true};
  if (!(geometry.overlap > 0.0)) {
    result.status = NarrowPhaseStatus::separated;
    return result;
  }
  result.status = NarrowPhaseStatus::contact;
  geometry.curvature_i = body.curvature_with_normal(into_wall);
  geometry.curvature_j =
      SurfaceCurvature{0.0, 0.0, geometry.curvature_i.direction_1, -geometry.curvature_i.direction_2};
  pair_principal_directions(geometry, into_wall);
  geometry.relative = relative_curvature(geometry.curvature_i.principal(), {}, 0.0);  // a flat wall
  return result;
}

double wall_mean_radius_sum(const Ellipsoid& body) noexcept { return 2.0 * body.mean_radius(); }

}  // namespace ellc
