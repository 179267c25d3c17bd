#pragma once
// What a contact between two bodies looks like geometrically: the result type shared by the
// ellipsoid–ellipsoid narrow phase and the ellipsoid–wall contact, and the pairing of the two
// sides' principal directions into the angle α of the paper's eq. (5).

#include <Eigen/Core>

#include "ellc/geometry/ellipsoid.hpp"

namespace ellc {

struct ContactGeometry {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();            // midpoint of the two surface points
  Eigen::Vector3d normal = Eigen::Vector3d::UnitX();          // unit, from I towards J
  double overlap = 0.0;                                       // δ = (p_I − p_J)·n; > 0 in contact
  Eigen::Vector3d surface_point_i = Eigen::Vector3d::Zero();  // on I, outward normal +n
  Eigen::Vector3d surface_point_j = Eigen::Vector3d::Zero();  // on J, outward normal −n
  RelativeCurvature relative;                                 // A ≤ B of eq. (5): all the law needs of the curvatures
  // Each side's curvatures and the angle between them (for reporting; the narrow phase leaves
  // them at these defaults when NarrowPhaseOptions::surface_curvatures is off).
  SurfaceCurvature curvature_i;  // of I at surface_point_i
  SurfaceCurvature curvature_j;  // of J at surface_point_j (zero for a wall)
  double alpha = 0.0;            // angle between the κ1 directions of I and J, in [0, π/2]
};

// The angle α ∈ [0, π/2] between the κ1 directions (principal directions are lines, so α and
// π − α are the same; eq. (5) only sees cos 2α). Umbilic handling: where a side is umbilic
// (κ1 = κ2, e.g. a spheroid tip, a sphere, a wall) every tangent direction is principal, so that
// side takes the other side's directions (projected on its own tangent plane) and α = 0. Eq. (5)
// weights α by κ1 − κ2 of each side, so this choice changes A and B by nothing, and α never
// jumps with the rounding noise of a tangent frame. `normal` is the outward normal of side I.
// Sets geometry.alpha (and may turn an umbilic side's directions).
void pair_principal_directions(ContactGeometry& geometry, const Eigen::Vector3d& normal) noexcept;

}  // namespace ellc
