#include "ellc/contact/pair_contact.hpp"

#include <algorithm>
#include <cmath>

namespace ellc {

namespace {

const ContactConstants& cached_constants(ContactCache& cache, PrincipalCurvatures body_i, PrincipalCurvatures body_j,
                                         double mean_radius_sum, const InteractionContext& context) noexcept {
  if (!cache.constants_cached) {
    cache.constants = make_contact_constants(context.material, body_i, body_j, 0.0, mean_radius_sum,
                                             context.model.hertz, context.model.law);
    cache.constants_cached = true;
  }
  return cache.constants;
}

void record_contact(PairSolution& solution, ContactHistory& history, ContactCache& cache) noexcept {
  history.max_overlap = solution.law.max_overlap;
  cache.last_overlap = solution.overlap;
}

PairSolution sphere_pair(const BodyRef& body_i, const BodyRef& body_j, ContactHistory& history, ContactCache& cache,
                         const InteractionContext& context) noexcept {
  PairSolution solution;
  const double radius_i = body_i.semi_axes.x();
  const double radius_j = body_j.semi_axes.x();
  const Eigen::Vector3d joint = body_j.centre - body_i.centre;
  const double distance = joint.norm();
  const double overlap = radius_i + radius_j - distance;
  if (!(overlap > 0.0)) {
    solution.clearance = std::max(-overlap, 0.0);
    return solution;
  }
  if (!(distance > 0.0)) {
    solution.status = PairStatus::failed;  // coincident centres: no normal
    return solution;
  }
  solution.status = PairStatus::contact;
  solution.normal = joint / distance;
  solution.overlap = overlap;
  solution.point = body_i.centre + (radius_i - 0.5 * overlap) * solution.normal;
  const ContactConstants& constants =
      cached_constants(cache, {1.0 / radius_i, 1.0 / radius_i}, {1.0 / radius_j, 1.0 / radius_j},
                       body_i.mean_radius + body_j.mean_radius, context);
  const LawOnBranch law = evaluate_contact_on_branch(constants, overlap, history.max_overlap);
  solution.law = law.law;
  solution.branch = law.branch;
  solution.constants = &constants;
  record_contact(solution, history, cache);
  return solution;
}

PairSolution sphere_wall(const BodyRef& body, const WallPlane& wall, ContactHistory& history, ContactCache& cache,
                         const InteractionContext& context) noexcept {
  PairSolution solution;
  const double radius = body.semi_axes.x();
  const double gap = wall.side * (body.centre.z() - wall.position);  // centre height above the wall
  const double overlap = radius - gap;
  if (!(overlap > 0.0)) return solution;
  solution.status = PairStatus::contact;
  solution.normal = Eigen::Vector3d(0.0, 0.0, -wall.side);
  solution.overlap = overlap;
  solution.point = Eigen::Vector3d(body.centre.x(), body.centre.y(), wall.position);
  const ContactConstants& constants =
      cached_constants(cache, {1.0 / radius, 1.0 / radius}, {0.0, 0.0}, 2.0 * body.mean_radius, context);
  const LawOnBranch law = evaluate_contact_on_branch(constants, overlap, history.max_overlap);
  solution.law = law.law;
  solution.branch = law.branch;
  solution.constants = &constants;
  record_contact(solution, history, cache);
  return solution;
}

}  // namespace

PairSolution solve_pair(const BodyRef& body_i, const BodyRef& body_j, bool spheres, ContactHistory& history,
                        ContactCache& cache, const InteractionContext& context) noexcept {
  if (spheres) return sphere_pair(body_i, body_j, history, cache, context);
  return solve_ellipsoid_pair(body_i, body_j, history, cache, context);
}

PairSolution solve_wall(const BodyRef& body, const WallPlane& wall, bool sphere, ContactHistory& history,
                        ContactCache& cache, const InteractionContext& context) noexcept {
  if (sphere) return sphere_wall(body, wall, history, cache, context);
  return solve_ellipsoid_wall(body, wall, history, cache, context);
}

PairForces pair_forces(const PairSolution& solution, const Eigen::Vector3d& centre_i, const BodyMotion& motion_i,
                       const Eigen::Vector3d& centre_j, const BodyMotion& motion_j, const InteractionContext& context,
                       double dt, ContactHistory& history) noexcept {
  const Eigen::Vector3d lever_i = solution.point - centre_i;
  const Eigen::Vector3d lever_j = solution.point - centre_j;
  const ContactKinematics kinematics{solution.normal,
                                     motion_j.velocity + motion_j.angular_velocity.cross(lever_j) - motion_i.velocity -
                                         motion_i.angular_velocity.cross(lever_i),
                                     motion_i.mass * motion_j.mass / (motion_i.mass + motion_j.mass)};
  PairForces forces;
  forces.contact =
      contact_force(context, *solution.constants, solution.law.force, solution.branch, kinematics, dt, history);
  forces.torque_on_i = -lever_i.cross(forces.contact.on_j);
  forces.torque_on_j = lever_j.cross(forces.contact.on_j);
  return forces;
}

WallForces wall_forces(const PairSolution& solution, const Eigen::Vector3d& centre, const BodyMotion& motion,
                       double wall_velocity, const InteractionContext& context, double dt,
                       ContactHistory& history) noexcept {
  const Eigen::Vector3d lever = solution.point - centre;
  const ContactKinematics kinematics{
      solution.normal,
      Eigen::Vector3d(0.0, 0.0, wall_velocity) - motion.velocity - motion.angular_velocity.cross(lever), motion.mass};
  WallForces forces;
  forces.contact =
      contact_force(context, *solution.constants, solution.law.force, solution.branch, kinematics, dt, history);
  forces.lever_cross_force = lever.cross(forces.contact.on_j);
  return forces;
}

}  // namespace ellc
