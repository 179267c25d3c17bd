#include "contact_model.hpp"

#include <algorithm>
#include <cmath>

#include "ellc/geometry/normal_contact.hpp"
#include "ellc/response/normal_damping.hpp"
#include "ellc/response/tangential_spring.hpp"

namespace ellc_lammps {

Eigen::Vector3d angular_velocity(const Eigen::Vector3d& angular_momentum, const Eigen::Quaterniond& orientation,
                                 const Eigen::Vector3d& semi_axes, double mass) {
  const Eigen::Vector3d squared = semi_axes.cwiseProduct(semi_axes);
  const Eigen::Vector3d inertia{mass * (squared.y() + squared.z()) / 5.0, mass * (squared.x() + squared.z()) / 5.0,
                                mass * (squared.x() + squared.y()) / 5.0};
  const Eigen::Vector3d body_momentum = orientation.conjugate() * angular_momentum;
  return orientation * body_momentum.cwiseQuotient(inertia);
}

namespace {
// The common normal to rounding (unlike the built-in engine's one Newton step per time step: the
// restart tests compare split and single runs to 5·10⁻¹⁰, and a LAMMPS restart re-solves from
// what the restart file kept); A, B without the per-side curvatures, which only reporting needs.
constexpr ellc::NarrowPhaseOptions kNarrowPhase{.surface_curvatures = false};

void forget(double* history) { std::fill(history, history + HistoryLayout::size(), 0.0); }

Eigen::Vector3d point_velocity(const BodyState& body, const ellc::Ellipsoid& shape, const Eigen::Vector3d& point) {
  return body.velocity + body.angular_velocity.cross(point - shape.center());
}

ellc::NarrowPhaseWarmStart read_warm_start(const double* history) {
  ellc::NarrowPhaseWarmStart warm;
  std::copy(history + HistoryLayout::warm_normal, history + HistoryLayout::warm_normal + 3, warm.normal.begin());
  warm.valid = history[HistoryLayout::warm_valid] != 0.0;
  return warm;
}

void write_warm_start(const ellc::NarrowPhaseWarmStart& warm, double* history) {
  std::copy(warm.normal.begin(), warm.normal.end(), history + HistoryLayout::warm_normal);
  history[HistoryLayout::warm_valid] = warm.valid ? 1.0 : 0.0;
}
}  // namespace

PairResult evaluate_pair(const BodyState& a, const BodyState& b, const PairCoefficients& coefficients,
                         ellc::HertzMode mode, double timestep, double* history) {
  const ellc::Ellipsoid body_a(a.semi_axes, {a.position, a.orientation});
  const ellc::Ellipsoid body_b(b.semi_axes, {b.position, b.orientation});
  return evaluate_pair({body_a, body_a.mean_radius(), a}, {body_b, body_b.mean_radius(), b}, coefficients, mode,
                       timestep, history);
}

PairResult evaluate_pair(const PosedBody& posed_a, const PosedBody& posed_b, const PairCoefficients& coefficients,
                         ellc::HertzMode mode, double timestep, double* history) {
  PairResult result;
  const ellc::Ellipsoid& body_a = posed_a.ellipsoid;
  const ellc::Ellipsoid& body_b = posed_b.ellipsoid;
  const BodyState& a = posed_a.motion;
  const BodyState& b = posed_b.motion;
  const ellc::NarrowPhaseWarmStart warm = read_warm_start(history);
  const ellc::NarrowPhaseResult narrow = ellc::ellipsoid_contact(body_a, body_b, &warm, kNarrowPhase);
  result.iterations = narrow.iterations;
  if (narrow.status != ellc::NarrowPhaseStatus::contact) {
    forget(history);  // history starts at δ > 0 and ends at δ ≤ 0 (model-notes §5)
    result.geometry_failed = narrow.status == ellc::NarrowPhaseStatus::failed;
    // A separating axis is kept as the next step's warm start: the narrow phase then proves
    // separation without its cold start. It is geometry, not contact history (δ_* is zero).
    if (narrow.status == ellc::NarrowPhaseStatus::separated && narrow.warm_start.valid) {
      write_warm_start(narrow.warm_start, history);
      result.keep_warm_start = true;
    }
    return result;
  }
  const ellc::ContactGeometry& geometry = narrow.geometry;
  write_warm_start(narrow.warm_start, history);
  result.touching = true;
  result.overlap = geometry.overlap;
  result.normal = geometry.normal;
  result.point = geometry.point;
  const Eigen::Vector3d& n = geometry.normal;

  // Normal: the Becker–Kamlah law with δ_* from the history, through the geometry layer.
  const ellc::NormalContact normal =
      ellc::normal_contact(geometry, coefficients.material, posed_a.mean_radius + posed_b.mean_radius, mode,
                           coefficients.law, history[HistoryLayout::max_overlap]);
  result.law = normal.law;
  history[HistoryLayout::max_overlap] = normal.law.max_overlap;

  // Damping and friction scale with the Hertz tangent stiffness k_n = dF_H/dδ; k_t = ratio × k_n.
  // This parametrisation is LAMMPS's; the algorithms are src/ellc/response's, shared with the engine.
  const double effective_mass = a.mass * b.mass / (a.mass + b.mass);
  const double normal_stiffness = 1.5 * normal.constants.hertz_coefficient * std::sqrt(geometry.overlap);
  const Eigen::Vector3d relative_velocity = point_velocity(b, body_b, geometry.point) - point_velocity(a, body_a, geometry.point);
  const double normal_speed = relative_velocity.dot(n);  // > 0 when separating
  result.normal_force = ellc::damped_normal_force(
      normal.law.force, ellc::viscous_damping(coefficients.normal_damping, effective_mass, normal_stiffness),
      normal_speed);

  // Tangential: spring ξ (displacement of b relative to a), kept in the current tangent plane.
  const double tangential_stiffness = coefficients.tangential_stiffness * normal_stiffness;
  const double tangential_damping =
      ellc::viscous_damping(coefficients.tangential_damping, effective_mass, tangential_stiffness);
  const ellc::TangentialCoefficients tangential{tangential_stiffness, tangential_damping, coefficients.friction};
  Eigen::Map<Eigen::Vector3d> spring(history + HistoryLayout::spring);
  const ellc::TangentialResponse friction =
      ellc::tangential_response(spring, n, relative_velocity, timestep, result.normal_force, tangential);
  spring = friction.spring;
  const Eigen::Vector3d force_on_b = result.normal_force * n + friction.force;

  result.force_on_b = force_on_b;
  result.torque_on_a = (geometry.point - body_a.center()).cross(-force_on_b);
  result.torque_on_b = (geometry.point - body_b.center()).cross(force_on_b);
  return result;
}

}  // namespace ellc_lammps
