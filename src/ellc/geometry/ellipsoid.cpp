#include "ellc/geometry/ellipsoid.hpp"

#include <numbers>

namespace ellc {

namespace {

// R diag(d) Rᵀ, each of the six distinct entries computed once: exactly symmetric by construction,
// at a third of the cost of two general 3×3 products (the DEM engine poses every particle each step).
Eigen::Matrix3d rotated_diagonal(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& diagonal) noexcept {
  Eigen::Matrix3d result;
  for (int row = 0; row < 3; ++row) {
    const Eigen::Vector3d scaled_row = rotation.row(row).transpose().cwiseProduct(diagonal);
    for (int column = row; column < 3; ++column) {
      result(row, column) = scaled_row.dot(rotation.row(column).transpose());
      result(column, row) = result(row, column);
    }
  }
  return result;
}

}  // namespace

Ellipsoid::Ellipsoid(const Eigen::Vector3d& semi_axes, const Pose& pose) noexcept : semi_axes_(semi_axes) {
  axes_valid_ = semi_axes_.allFinite() && (semi_axes_.array() > 0.0).all();
  shape_diagonal_ = semi_axes_.array().square().inverse();
  set_pose(pose);
}

void Ellipsoid::set_pose(const Pose& pose) noexcept {
  pose_ = pose;
  const double quaternion_norm = pose_.orientation.norm();
  const bool quaternion_ok = std::isfinite(quaternion_norm) && quaternion_norm > 0.0;
  if (quaternion_ok) {
    pose_.orientation.coeffs() /= quaternion_norm;
  } else {
    pose_.orientation = Eigen::Quaterniond::Identity();
  }
  shape_valid_ = quaternion_ok && axes_valid_;
  valid_ = shape_valid_ && pose_.position.allFinite();
  rotation_ = pose_.orientation.toRotationMatrix();
  inverse_shape_ = rotated_diagonal(rotation_, semi_axes_.array().square().matrix());
  shape_ = rotated_diagonal(rotation_, shape_diagonal_);
}

Eigen::Vector3d Ellipsoid::support_point(const Eigen::Vector3d& direction) const noexcept {
  const Eigen::Vector3d image = inverse_shape_ * direction;
  return pose_.position + image / std::sqrt(direction.dot(image));
}

Eigen::Vector3d Ellipsoid::surface_point_with_normal(const Eigen::Vector3d& world_normal) const noexcept {
  return support_point(world_normal);  // scale-free: S n / sqrt(nᵀ S n) does not depend on |n|
}

SurfaceCurvature curvature_from_shape_operator(double w11, double w12, double w22,
                                               const geometry_detail::TangentFrame& frame,
                                               const Eigen::Vector3d& outward_normal) noexcept {
  const auto eigen = geometry_detail::symmetric_eigen2(w11, w12, w22, SurfaceCurvature::umbilic_tolerance);
  SurfaceCurvature curvature;
  curvature.kappa_1 = eigen.high;
  curvature.kappa_2 = eigen.low;
  curvature.direction_1 = eigen.x * frame.t1 + eigen.y * frame.t2;
  curvature.direction_2 = outward_normal.cross(curvature.direction_1);
  return curvature;
}

SurfaceCurvature Ellipsoid::curvature_in_frame(const Eigen::Vector3d& outward_normal,
                                               const geometry_detail::TangentFrame& frame,
                                               double inverse_gradient_norm) const noexcept {
  // Wₐᵦ = tₐᵀ M_w tᵦ / |M_w (x − c)| (the factors 2 of ∇F = 2 M_w (x − c) and ∇²F = 2 M_w cancel).
  const Eigen::Vector3d m_t1 = shape_ * frame.t1;
  const Eigen::Vector3d m_t2 = shape_ * frame.t2;
  return curvature_from_shape_operator(frame.t1.dot(m_t1) * inverse_gradient_norm,
                                       frame.t2.dot(m_t1) * inverse_gradient_norm,
                                       frame.t2.dot(m_t2) * inverse_gradient_norm, frame, outward_normal);
}

SurfaceCurvature Ellipsoid::curvature_with_normal(const Eigen::Vector3d& world_normal) const noexcept {
  const Eigen::Vector3d normal = world_normal.normalized();
  return curvature_in_frame(normal, geometry_detail::tangent_frame(normal), support_radius(normal));
}

SurfaceCurvature Ellipsoid::curvature_at(const Eigen::Vector3d& world_surface_point) const noexcept {
  Eigen::Vector3d body_point = to_body(world_surface_point);
  const double level = body_point.dot(shape_diagonal_.cwiseProduct(body_point));
  if (level > 0.0)
    body_point /= std::sqrt(level);  // radial projection onto the surface
  else
    body_point = semi_axes_.x() * Eigen::Vector3d::UnitX();  // the centre itself: any point will do
  const Eigen::Vector3d gradient = rotation_ * shape_diagonal_.cwiseProduct(body_point);
  const double gradient_norm = gradient.norm();
  const Eigen::Vector3d normal = gradient / gradient_norm;
  return curvature_in_frame(normal, geometry_detail::tangent_frame(normal), 1.0 / gradient_norm);
}

Eigen::Vector3d Ellipsoid::normal_at(const Eigen::Vector3d& world_point) const noexcept {
  const Eigen::Vector3d gradient = shape_diagonal_.cwiseProduct(to_body(world_point));
  const double norm = gradient.norm();
  if (!(norm > 0.0)) return rotation_.col(0);
  return rotation_ * (gradient / norm);
}

double Ellipsoid::implicit_value(const Eigen::Vector3d& world_point) const noexcept {
  const Eigen::Vector3d body_point = to_body(world_point);
  return body_point.dot(shape_diagonal_.cwiseProduct(body_point)) - 1.0;
}

OrientedBox Ellipsoid::bounding_box() const noexcept { return {pose_.position, rotation_, semi_axes_}; }

AxisAlignedBox Ellipsoid::axis_aligned_bounds() const noexcept {
  // The support radius along world axis k is sqrt(S_kk).
  const Eigen::Vector3d half = inverse_shape_.diagonal().cwiseSqrt();
  return {pose_.position - half, pose_.position + half};
}

double Ellipsoid::volume() const noexcept { return 4.0 / 3.0 * std::numbers::pi * semi_axes_.prod(); }

double Ellipsoid::mean_radius() const noexcept { return std::cbrt(semi_axes_.prod()); }

}  // namespace ellc
