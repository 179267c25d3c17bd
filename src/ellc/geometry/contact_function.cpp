#include "ellc/geometry/contact_function.hpp"

#include <Eigen/LU>

#include <cmath>

namespace ellc {

ContactFunctionResult perram_wertheim(const Ellipsoid& body_i, const Ellipsoid& body_j, bool stop_when_separated,
                                      double lambda_tolerance) noexcept {
  ContactFunctionResult result;
  const Eigen::Vector3d r = body_j.center() - body_i.center();
  const double distance = r.norm();
  if (!(distance > 0.0)) return result;
  const Eigen::Matrix3d& shape_i = body_i.inverse_shape();
  const Eigen::Matrix3d& shape_j = body_j.inverse_shape();
  const Eigen::Matrix3d shape_change = shape_j - shape_i;  // dC/dλ

  // Start at the maximiser for two spheres of the bodies' reach along r: ρ_I / (ρ_I + ρ_J).
  const Eigen::Vector3d axis = r / distance;
  const double reach_i = body_i.support_radius(axis);
  const double reach_j = body_j.support_radius(axis);
  double lambda = reach_i / (reach_i + reach_j);
  double lower = 0.0;
  double upper = 1.0;
  constexpr int kMaxIterations = 60;
  for (int iteration = 1; iteration <= kMaxIterations; ++iteration) {
    result.iterations = iteration;
    const double weight = lambda * (1.0 - lambda);
    const Eigen::Matrix3d combined_inverse = ((1.0 - lambda) * shape_i + lambda * shape_j).inverse();
    const Eigen::Vector3d x = combined_inverse * r;
    const double r_x = r.dot(x);
    result.value = weight * r_x;
    result.lambda = lambda;
    const double x_norm = x.norm();
    if (x_norm > 0.0 && std::isfinite(x_norm)) result.normal = x / x_norm;
    if (result.value > 1.0 && stop_when_separated) {
      result.separated = true;
      result.converged = true;
      return result;
    }
    // F' = (1 − 2λ) rᵀx − λ(1 − λ) xᵀ E x,  F'' = −2 rᵀx − 2(1 − 2λ) xᵀ E x + 2 λ(1 − λ) (E x)ᵀ C⁻¹ (E x).
    const Eigen::Vector3d y = shape_change * x;
    const double x_y = x.dot(y);
    const double slope = (1.0 - 2.0 * lambda) * r_x - weight * x_y;
    const double curvature = -2.0 * r_x - 2.0 * (1.0 - 2.0 * lambda) * x_y + 2.0 * weight * y.dot(combined_inverse * y);
    if (slope == 0.0) {  // at the maximum
      result.separated = result.value > 1.0;
      result.converged = true;
      return result;
    }
    if (slope > 0.0)
      lower = lambda;
    else
      upper = lambda;
    double next = curvature < 0.0 ? lambda - slope / curvature : 0.5 * (lower + upper);
    if (!(next > lower && next < upper)) next = 0.5 * (lower + upper);  // Newton left the bracket: bisect
    const bool done = std::abs(next - lambda) <= lambda_tolerance || upper - lower <= lambda_tolerance;
    lambda = next;
    if (done) {
      result.separated = result.value > 1.0;
      result.converged = true;
      return result;
    }
  }
  result.separated = result.value > 1.0;
  return result;
}

}  // namespace ellc
