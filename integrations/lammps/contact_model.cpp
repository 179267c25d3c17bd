#include "contact_model.hpp"

#include <algorithm>
#include <cmath>

#include "contact_geometry.hpp"
#include "ellc/geometry/tip_contact.hpp"
#include "ellc/law/contact_constants.hpp"

namespace ellc_lammps {

int HistoryLayout::size() { return warm_start + warm_start_size(); }

Eigen::Vector3d angular_velocity(const Eigen::Vector3d& angular_momentum, const Eigen::Quaterniond& orientation,
                                 const Eigen::Vector3d& semi_axes, double mass) {
  const Eigen::Vector3d squared = semi_axes.cwiseProduct(semi_axes);
  const Eigen::Vector3d inertia{mass * (squared.y() + squared.z()) / 5.0, mass * (squared.x() + squared.z()) / 5.0,
                                mass * (squared.x() + squared.y()) / 5.0};
  const Eigen::Vector3d body_momentum = orientation.conjugate() * angular_momentum;
  return orientation * body_momentum.cwiseQuotient(inertia);
}

namespace {
void forget(double* history) { std::fill(history, history + HistoryLayout::size(), 0.0); }

Eigen::Vector3d point_velocity(const BodyState& body, const Eigen::Vector3d& point) {
  return body.velocity + body.angular_velocity.cross(point - body.position);
}
}  // namespace

PairResult evaluate_pair(const BodyState& a, const BodyState& b, const PairCoefficients& coefficients,
                         ellc::HertzMode mode, double timestep, double* history) {
  PairResult result;
  const PairGeometry geometry = pair_geometry(a, b, history + HistoryLayout::warm_start);
  if (!geometry.valid || !(geometry.overlap > 0.0)) {
    forget(history);
    result.geometry_failed = !geometry.valid;
    return result;
  }
  result.touching = true;
  result.overlap = geometry.overlap;
  result.normal = geometry.normal;
  result.point = geometry.point;
  const Eigen::Vector3d& n = geometry.normal;

  // Normal: the Becker–Kamlah law with δ_* from the history.
  const double mean_radius_sum = ellc::mean_radius(a.semi_axes) + ellc::mean_radius(b.semi_axes);
  const ellc::ContactConstants constants =
      ellc::make_contact_constants(coefficients.material, geometry.curvature_a, geometry.curvature_b, geometry.alpha,
                                   mean_radius_sum, mode, coefficients.law);
  result.law = ellc::evaluate_contact(constants, geometry.overlap, history[HistoryLayout::max_overlap]);
  history[HistoryLayout::max_overlap] = result.law.max_overlap;

  // Damping and friction scale with the Hertz tangent stiffness k_n = dF_H/dδ.
  const double effective_mass = a.mass * b.mass / (a.mass + b.mass);
  const double normal_stiffness = 1.5 * constants.hertz_coefficient * std::sqrt(geometry.overlap);
  const Eigen::Vector3d relative_velocity = point_velocity(b, geometry.point) - point_velocity(a, geometry.point);
  const double normal_speed = relative_velocity.dot(n);  // > 0 when separating
  const double normal_damping = 2.0 * coefficients.normal_damping * std::sqrt(effective_mass * normal_stiffness);
  result.normal_force = std::max(result.law.force - normal_damping * normal_speed, 0.0);

  // Tangential: spring ξ (displacement of b relative to a), kept in the current tangent plane.
  Eigen::Vector3d force_on_b = result.normal_force * n;
  Eigen::Map<Eigen::Vector3d> spring(history + HistoryLayout::spring);
  const double tangential_stiffness = coefficients.tangential_stiffness * normal_stiffness;
  if (coefficients.friction > 0.0 && tangential_stiffness > 0.0) {
    const double length = spring.norm();
    spring -= spring.dot(n) * n;
    const double projected = spring.norm();
    if (projected > 0.0) spring *= length / projected;
    const Eigen::Vector3d tangential_velocity = relative_velocity - normal_speed * n;
    spring += tangential_velocity * timestep;
    const double tangential_damping =
        2.0 * coefficients.tangential_damping * std::sqrt(effective_mass * tangential_stiffness);
    Eigen::Vector3d tangential = -tangential_stiffness * spring - tangential_damping * tangential_velocity;
    const double limit = coefficients.friction * result.normal_force;
    const double magnitude = tangential.norm();
    if (magnitude > limit) {  // sliding: cap at the Coulomb limit and pull the spring back to it
      tangential *= magnitude > 0.0 ? limit / magnitude : 0.0;
      spring = -(tangential + tangential_damping * tangential_velocity) / tangential_stiffness;
    }
    force_on_b += tangential;
  } else {
    spring.setZero();
  }

  result.force_on_b = force_on_b;
  result.torque_on_a = (geometry.point - a.position).cross(-force_on_b);
  result.torque_on_b = (geometry.point - b.position).cross(force_on_b);
  return result;
}

}  // namespace ellc_lammps
