#pragma once
// Ellipsoid–plane (wall) contact. The wall is body J with zero curvatures, so the contact law
// becomes Hertz between the ellipsoid and a flat (docs/model.md §1). Closed form: the deepest point
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

// r̂^{I,J} (paper eq. 50) for a wall contact, by convention 2 r̂ of the particle: a flat wall
// has no finite r̂, so it is given that of the particle's mirror image in the plane. This keeps
// R_e/r̂^{I,J} finite (a sphere on a wall: 1/2; two equal spheres: 1/4). The transition fits
// were calibrated on particle pairs only; docs/geometry.md §4.
[[nodiscard]] double wall_mean_radius_sum(const Ellipsoid& body) noexcept;

}  // namespace ellc
