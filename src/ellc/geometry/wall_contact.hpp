#pragma once
// Ellipsoid–plane (wall) contact. The wall is body J with zero curvatures, so the contact law
// becomes Hertz between the ellipsoid and a flat (model-notes §1). Closed form: the deepest point
// of the body is its support point along −normal; no iteration, no warm start.

#include <Eigen/Core>

#include "ellc/geometry/ellipsoid.hpp"
#include "ellc/geometry/narrow_phase.hpp"

namespace ellc {

struct Plane {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // unit, into the half-space where the particles live
};

// Body = I, wall = J: geometry.normal = −wall.normal (from the body into the wall),
// surface_point_i = the body's deepest point, surface_point_j = its projection on the plane,
// overlap = its depth below the plane (minus the gap when separated, exact), curvature_j = 0 with
// the body's directions (α = 0). The wall normal is normalised here; a zero or non-finite wall,
// or an invalid body, gives status failed.
[[nodiscard]] NarrowPhaseResult wall_contact(const Ellipsoid& body, const Plane& wall) noexcept;

// r̂^{I,J} (paper eq. 50) for a wall contact: the wall is treated as the mirror image of the
// particle in the plane, the symmetric two-body problem whose mid-plane is the wall, so
// r̂^{I,J} = 2 r̂ of the particle. The law's transition fits (eq. 52–53) then see the same R_e/r̂
// as for two identical particles touching at the same point.
[[nodiscard]] double wall_mean_radius_sum(const Ellipsoid& body) noexcept;

}  // namespace ellc
