// Interim narrow phase: the tip-to-tip configuration of the paper (Sec. 5), exact when both
// bodies have their x semi-axis along the line of centres, and for spheres in any orientation.
// Replaced by the general narrow phase of the geometry layer when it is available.

#include <cmath>

#include "contact_geometry.hpp"
#include "ellc/geometry/tip_contact.hpp"

namespace ellc_lammps {

int warm_start_size() { return 0; }

namespace {
// Angle of the body's y axis about `axis`, measured from a reference perpendicular to `axis`.
double twist_about(const Eigen::Quaterniond& orientation, const Eigen::Vector3d& axis) {
  Eigen::Vector3d reference = axis.cross(Eigen::Vector3d::UnitZ());
  if (reference.norm() < 1e-8) reference = axis.cross(Eigen::Vector3d::UnitY());
  reference.normalize();
  const Eigen::Vector3d y_axis = orientation * Eigen::Vector3d::UnitY();
  return std::atan2(reference.cross(y_axis).dot(axis), reference.dot(y_axis));
}

bool is_sphere(const Eigen::Vector3d& semi_axes) {
  return semi_axes.x() == semi_axes.y() && semi_axes.y() == semi_axes.z();
}
}  // namespace

PairGeometry pair_geometry(const BodyState& a, const BodyState& b, double* /*warm_start*/) {
  PairGeometry geometry;
  const Eigen::Vector3d separation = b.position - a.position;
  const double distance = separation.norm();
  geometry.normal = separation / distance;
  for (const BodyState* body : {&a, &b}) {
    if (is_sphere(body->semi_axes)) continue;
    const Eigen::Vector3d x_axis = body->orientation * Eigen::Vector3d::UnitX();
    if (std::abs(std::abs(x_axis.dot(geometry.normal)) - 1.0) > 1e-9) geometry.valid = false;
  }
  geometry.overlap = a.semi_axes.x() + b.semi_axes.x() - distance;
  geometry.point = a.position + geometry.normal * (a.semi_axes.x() - 0.5 * geometry.overlap);
  const ellc::TipContact tip = ellc::tip_contact({a.semi_axes, twist_about(a.orientation, geometry.normal)},
                                                 {b.semi_axes, twist_about(b.orientation, geometry.normal)});
  geometry.curvature_a = tip.body_i;
  geometry.curvature_b = tip.body_j;
  geometry.alpha = tip.alpha;
  return geometry;
}

}  // namespace ellc_lammps
