#pragma once
// The paper's validation geometry (Sec. 5): two ellipsoids with semi-axis a along the
// compression axis x, touching at the tips of their x semi-axes, each twisted about x by its own
// angle. At the tip (a, 0, 0) the principal curvatures are a/b² (along y) and a/c² (along z).
// The general pose (any orientation, any contact point) lives in the narrow phase; both end in
// the same PrincipalCurvatures + α that the Hertz layer takes.

#include <Eigen/Core>

#include "ellc/hertz/elliptic_hertz.hpp"

namespace ellc {

// Semi-axes (a, b, c) with a along the line of centres, and the twist about that axis.
struct TipBody {
  Eigen::Vector3d semi_axes{1.0, 1.0, 1.0};
  double twist = 0.0;  // radians: rotation of the body's (y, z) axes about x
};

struct TipContact {
  PrincipalCurvatures body_i;  // κ1 along the body's twisted y axis, κ2 along its twisted z axis
  PrincipalCurvatures body_j;
  double alpha = 0.0;  // angle between the κ1 directions of I and J (Fig. 1)
};

// r̂^k = (a b c)^{1/3}, eq. (50).
[[nodiscard]] double mean_radius(const Eigen::Vector3d& semi_axes) noexcept;

// Curvatures at the x tip: (a/b², a/c²).
[[nodiscard]] PrincipalCurvatures tip_curvatures(const Eigen::Vector3d& semi_axes) noexcept;

[[nodiscard]] TipContact tip_contact(const TipBody& body_i, const TipBody& body_j) noexcept;

}  // namespace ellc
