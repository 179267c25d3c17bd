#include "pair_adapter.hpp"

#include "ellc/contact/pair_contact.hpp"

namespace ellc_lammps {

PairEvaluation evaluate_pair(const BodyState& a, const BodyState& b, const ellc::InteractionContext& context,
                             double timestep, double* history) {
  const ellc::Ellipsoid body_a(a.semi_axes, {a.position, a.orientation});
  const ellc::Ellipsoid body_b(b.semi_axes, {b.position, b.orientation});
  ellc::ContactCache scratch;
  return evaluate_pair({body_a, body_a.mean_radius(), a}, {body_b, body_b.mean_radius(), b}, context, timestep, history,
                       scratch);
}

PairEvaluation evaluate_pair(const AtomBody& a, const AtomBody& b, const ellc::InteractionContext& context,
                             double timestep, double* history, ellc::ContactCache& cache) {
  ellc::ContactHistory record = ellc::ContactHistory::read_from(history);
  // The constants are rebuilt every step (nothing per contact but the record). The ellipsoid path
  // overwrites cache.constants before use and never reads constants_cached (the sphere path's).
  const BodyState& motion_a = a.motion;
  const BodyState& motion_b = b.motion;
  const ellc::BodyRef ref_a{motion_a.semi_axes, a.ellipsoid.center(), motion_a.orientation, a.mean_radius,
                            &a.ellipsoid};
  const ellc::BodyRef ref_b{motion_b.semi_axes, b.ellipsoid.center(), motion_b.orientation, b.mean_radius,
                            &b.ellipsoid};
  // Always the narrow phase, spheres included: LAMMPS keeps a separating axis for every pair in
  // its neighbor list, which the closed-form sphere path does not provide.
  const ellc::PairSolution solution = ellc::solve_pair(ref_a, ref_b, false, record, cache, context);
  PairEvaluation result;
  result.iterations = solution.iterations;
  if (solution.status == ellc::PairStatus::failed) {
    result.geometry_failed = true;
    return result;
  }
  if (solution.status == ellc::PairStatus::separated) {
    record.end_contact();  // history starts at δ > 0 and ends at δ ≤ 0 (docs/model.md §5)
    result.keep_warm_start = record.warm_valid != 0.0;
    result.clearance = solution.clearance;
    if (!result.keep_warm_start) record = ellc::ContactHistory{};
    record.write_to(history);
    return result;
  }
  result.touching = true;
  result.overlap = solution.overlap;
  result.normal = solution.normal;
  result.point = solution.point;
  result.law = solution.law;
  result.contact_radius_sq_per_overlap = solution.constants->contact_radius_sq_per_overlap;
  if (solution.law.regime != ellc::Regime::separated) {  // below δ_p the bodies overlap but carry nothing
    const ellc::PairForces forces = ellc::pair_forces(
        solution, a.ellipsoid.center(), {motion_a.velocity, motion_a.angular_velocity, motion_a.mass},
        b.ellipsoid.center(), {motion_b.velocity, motion_b.angular_velocity, motion_b.mass}, context, timestep, record);
    result.force_on_b = forces.contact.on_j;
    result.normal_force = forces.contact.on_j.dot(solution.normal);  // F_t ⊥ n
    result.torque_on_a = forces.torque_on_i;
    result.torque_on_b = forces.torque_on_j;
  }
  record.write_to(history);
  return result;
}

}  // namespace ellc_lammps
