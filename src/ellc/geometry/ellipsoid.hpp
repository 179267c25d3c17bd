#pragma once
// A posed ellipsoid: semi-axes (a, b, c) along its body x, y, z axes, a centre and a unit
// quaternion (body → world). The surface is the implicit x_bᵀ M x_b = 1 with M = diag(a⁻², b⁻², c⁻²)
// in the body frame; everything here (normals, support points, curvatures) follows from the
// gradient 2 M x_b and the Hessian 2 M of that implicit function, so no point of the surface is
// special (unlike the paper's x(y, z) parametrisation, Appendix A, which breaks down at x = 0).
//
// Value type. The constructor caches the rotation matrix and the world-frame inverse shape matrix
// S = R D² Rᵀ (D = diag(a, b, c)), so every query below is a few fixed-size products: no
// allocation, noexcept. An ellipsoid built from non-finite or non-positive data is !valid(); the
// narrow phase reports such pairs as failed instead of computing with them.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>

#include "ellc/geometry/tangent_frame.hpp"
#include "ellc/hertz/elliptic_hertz.hpp"

namespace ellc {

struct Pose {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  // body → world
};

// Principal curvatures (1/length, > 0 on an ellipsoid, 0 on a wall) with κ1 ≥ κ2 and their unit
// tangent directions in the world frame; direction_2 = normal × direction_1.
struct SurfaceCurvature {
  double kappa_1 = 0.0;
  double kappa_2 = 0.0;
  Eigen::Vector3d direction_1 = Eigen::Vector3d::UnitX();
  Eigen::Vector3d direction_2 = Eigen::Vector3d::UnitY();

  [[nodiscard]] PrincipalCurvatures principal() const noexcept { return {kappa_1, kappa_2}; }
  // κ1 − κ2 below this fraction of κ1 + κ2: an umbilic, where every tangent direction is principal.
  static constexpr double umbilic_tolerance = 1e-11;
  [[nodiscard]] bool umbilic() const noexcept {
    return kappa_1 - kappa_2 <= umbilic_tolerance * (std::abs(kappa_1) + std::abs(kappa_2));
  }
};

// Box with centre, orthonormal axes (columns, world frame) and half extents along them.
struct OrientedBox {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
  Eigen::Vector3d half_extents = Eigen::Vector3d::Zero();
};

// World-axis-aligned bounds (for a broad phase): the tightest box around the ellipsoid.
struct AxisAlignedBox {
  Eigen::Vector3d lower = Eigen::Vector3d::Zero();
  Eigen::Vector3d upper = Eigen::Vector3d::Zero();
};

// κ1 ≥ κ2 and the principal directions from a shape operator given by its entries
// W₁₁, W₁₂, W₂₂ in the tangent frame (t₁, t₂) of `outward_normal` (direction_2 = n × direction_1).
[[nodiscard]] SurfaceCurvature curvature_from_shape_operator(double w11, double w12, double w22,
                                                             const geometry_detail::TangentFrame& frame,
                                                             const Eigen::Vector3d& outward_normal) noexcept;

class Ellipsoid {
 public:
  // The quaternion is normalised here; a zero or non-finite quaternion, or semi-axes that are
  // not finite and > 0, make the ellipsoid !valid() (its queries still return finite numbers).
  Ellipsoid(const Eigen::Vector3d& semi_axes, const Pose& pose = {}) noexcept;  // NOLINT: implicit by design of the API

  [[nodiscard]] const Eigen::Vector3d& semi_axes() const noexcept { return semi_axes_; }
  [[nodiscard]] const Pose& pose() const noexcept { return pose_; }
  [[nodiscard]] const Eigen::Vector3d& center() const noexcept { return pose_.position; }
  // Body → world rotation; its columns are the body axes in the world frame.
  [[nodiscard]] const Eigen::Matrix3d& rotation() const noexcept { return rotation_; }
  // S = R D² Rᵀ: the support point in direction n is c + S n / sqrt(nᵀ S n).
  [[nodiscard]] const Eigen::Matrix3d& inverse_shape() const noexcept { return inverse_shape_; }
  // M_w = R D⁻² Rᵀ: the surface is (x − c)ᵀ M_w (x − c) = 1 (world frame).
  [[nodiscard]] const Eigen::Matrix3d& shape() const noexcept { return shape_; }
  [[nodiscard]] bool valid() const noexcept { return valid_; }
  // The same ellipsoid with its centre at `center` (a periodic image): the same orientation and
  // matrices, bit for bit as if built anew there, without the quaternion and the matrix products.
  [[nodiscard]] Ellipsoid moved_to(const Eigen::Vector3d& center) const noexcept {
    Ellipsoid moved = *this;
    moved.pose_.position = center;
    moved.valid_ = shape_valid_ && center.allFinite();
    return moved;
  }
  // Poses this ellipsoid anew, in place: bit for bit Ellipsoid(semi_axes(), pose), without the
  // semi-axes' part and a copy of the whole object (a DEM re-poses every particle every step).
  void set_pose(const Pose& pose) noexcept;

  // The surface point whose outward unit normal is `world_normal` (normalised here).
  [[nodiscard]] Eigen::Vector3d surface_point_with_normal(const Eigen::Vector3d& world_normal) const noexcept;
  // The point of the body farthest along `direction` (any length > 0): the same point.
  [[nodiscard]] Eigen::Vector3d support_point(const Eigen::Vector3d& direction) const noexcept;
  // h(n) − n·c = sqrt(nᵀ S n) for a unit n: how far the body reaches from its centre along n.
  [[nodiscard]] double support_radius(const Eigen::Vector3d& unit_direction) const noexcept {
    return std::sqrt(unit_direction.dot(inverse_shape_ * unit_direction));
  }

  // Principal curvatures and directions at a surface point. The point is first pulled radially
  // onto the surface, so points a rounding error off the surface are fine. Shape operator of the
  // implicit surface F(x) = (x − c)ᵀ M_w (x − c) − 1: W = P (∇²F) P / |∇F| on the tangent plane
  // (P = I − n nᵀ, n = ∇F/|∇F|), i.e. Wₐᵦ = tₐᵀ M_w tᵦ / |M_w (x − c)| in a tangent frame.
  // At an umbilic (κ1 = κ2 to SurfaceCurvature::umbilic_tolerance) the directions are the
  // tangent frame of the normal (deterministic, never NaN).
  [[nodiscard]] SurfaceCurvature curvature_at(const Eigen::Vector3d& world_surface_point) const noexcept;
  // The same at the surface point with outward unit normal `world_normal` (there |M_w (x − c)| = 1/ρ(n)).
  [[nodiscard]] SurfaceCurvature curvature_with_normal(const Eigen::Vector3d& world_normal) const noexcept;
  // The same for callers that already hold a tangent frame of the outward normal and
  // 1/|M_w (x − c)| at the point (= the support radius ρ(n) at the point with normal n).
  [[nodiscard]] SurfaceCurvature curvature_in_frame(const Eigen::Vector3d& outward_normal,
                                                    const geometry_detail::TangentFrame& frame,
                                                    double inverse_gradient_norm) const noexcept;
  // Outward unit normal at (the radial projection onto the surface of) a point.
  [[nodiscard]] Eigen::Vector3d normal_at(const Eigen::Vector3d& world_point) const noexcept;
  // x_bᵀ M x_b − 1: < 0 inside, 0 on the surface, > 0 outside.
  [[nodiscard]] double implicit_value(const Eigen::Vector3d& world_point) const noexcept;

  [[nodiscard]] double bounding_radius() const noexcept { return semi_axes_.maxCoeff(); }  // sphere at the centre
  [[nodiscard]] OrientedBox bounding_box() const noexcept;
  [[nodiscard]] AxisAlignedBox axis_aligned_bounds() const noexcept;
  [[nodiscard]] double volume() const noexcept;       // (4/3) π a b c
  [[nodiscard]] double mean_radius() const noexcept;  // r̂ = (a b c)^{1/3}, paper eq. (50)

 private:
  [[nodiscard]] Eigen::Vector3d to_body(const Eigen::Vector3d& world_point) const noexcept {
    return rotation_.transpose() * (world_point - pose_.position);
  }

  Eigen::Vector3d semi_axes_;
  Pose pose_;
  Eigen::Matrix3d rotation_;
  Eigen::Matrix3d inverse_shape_;
  Eigen::Matrix3d shape_;
  Eigen::Vector3d shape_diagonal_;  // M = diag(a⁻², b⁻², c⁻²), body frame
  bool axes_valid_ = false;         // semi-axes finite and > 0
  bool shape_valid_ = false;        // quaternion and semi-axes usable (valid_ also needs the centre)
  bool valid_ = false;
};

}  // namespace ellc
