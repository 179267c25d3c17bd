#pragma once
// From two posed bodies (or a body and a wall) to the forces on both: the narrow phase as both
// engines use it, then the contact model. Spheres take an exact closed-form path; ellipsoids go
// through the geometry layer's narrow phase (warm-started from the history) and normal_contact().
//
//   solve_pair / solve_wall     narrow phase + the law; stores δ_* in the history on contact
//   pair_forces / wall_forces   damping and the tangential spring (contact_model.hpp), torques
//
// The built-in engine and pair_style ellipsoid/bk call exactly these; neither has a force formula
// of its own.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

#include "ellc/contact/contact_force.hpp"
#include "ellc/contact/contact_history.hpp"
#include "ellc/contact/contact_model.hpp"
#include "ellc/geometry/ellipsoid.hpp"
#include "ellc/law/contact_law.hpp"

namespace ellc {

enum class PairStatus { contact, separated, failed };

struct PairSolution {
  PairStatus status = PairStatus::separated;
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // unit, I → J (body → wall for walls)
  Eigen::Vector3d point = Eigen::Vector3d::Zero();    // where the contact forces act
  double overlap = 0.0;
  // Separated: a clearance the bodies are proven apart by along one fixed axis (they stay apart
  // while their points move less than this in total), given only where re-testing the pair in
  // that time would change nothing (a caller may then skip it); 0 otherwise.
  double clearance = 0.0;
  int iterations = 0;  // narrow-phase Newton steps (0 on the closed-form and shortcut paths)
  LawResult law;
  ElasticBranch branch;                         // the curve the law was on (for the stiffnesses)
  const ContactConstants* constants = nullptr;  // points into the cache (valid while it lives)
};

// A posed body.
struct BodyRef {
  const Eigen::Vector3d& semi_axes;
  Eigen::Vector3d centre;  // image position for periodic neighbours
  const Eigen::Quaterniond& orientation;
  double mean_radius;                // r̂ = (abc)^{1/3}, eq. (50)
  const Ellipsoid* shape = nullptr;  // prebuilt for this step (ellipsoids; null → built on demand)
};

// The plane z = position, the particles on the side `side` (+1: above, a floor; −1: below).
struct WallPlane {
  double position = 0.0;
  int side = 1;
};

// The ellipsoid paths (pair_contact_ellipsoids.cpp), called by solve_pair and solve_wall below.
[[nodiscard]] PairSolution solve_ellipsoid_pair(const BodyRef& body_i, const BodyRef& body_j, ContactHistory& history,
                                                ContactCache& cache, const InteractionContext& context) noexcept;
[[nodiscard]] PairSolution solve_ellipsoid_wall(const BodyRef& body, const WallPlane& wall, ContactHistory& history,
                                                ContactCache& cache, const InteractionContext& context) noexcept;

struct BodyMotion {
  const Eigen::Vector3d& velocity;
  const Eigen::Vector3d& angular_velocity;  // world frame
  double mass;
};

struct PairForces {
  ContactForce contact;  // contact.on_j: the force on J; the force on I is −contact.on_j
  Eigen::Vector3d torque_on_i = Eigen::Vector3d::Zero();
  Eigen::Vector3d torque_on_j = Eigen::Vector3d::Zero();
};

struct WallForces {
  ContactForce contact;  // contact.on_j: the force on the wall; the force on the body is −contact.on_j
  Eigen::Vector3d lever_cross_force = Eigen::Vector3d::Zero();  // (x − c) × contact.on_j: −torque on the body
};

// Definitions. Inline, like contact_force(): the engines call them once per contact and step.
namespace pair_detail {

inline const ContactConstants& cached_constants(ContactCache& cache, PrincipalCurvatures body_i,
                                                PrincipalCurvatures body_j, double mean_radius_sum,
                                                const InteractionContext& context) noexcept {
  if (!cache.constants_cached) {
    cache.constants = make_contact_constants(context.material, body_i, body_j, 0.0, mean_radius_sum,
                                             context.model.hertz, context.model.law);
    cache.constants_cached = true;
  }
  return cache.constants;
}

// The law at the solution's overlap on the contact's constants; stores δ_* in the history and δ
// in the cache.
inline void apply_law(PairSolution& solution, const ContactConstants& constants, ContactHistory& history,
                      ContactCache& cache) noexcept {
  const LawOnBranch law = evaluate_contact_on_branch(constants, solution.overlap, history.max_overlap);
  solution.law = law.law;
  solution.branch = law.branch;
  solution.constants = &constants;
  history.max_overlap = solution.law.max_overlap;
  cache.last_overlap = solution.overlap;
}

[[nodiscard]] inline PairSolution sphere_pair(const BodyRef& body_i, const BodyRef& body_j, ContactHistory& history,
                                              ContactCache& cache, const InteractionContext& context) noexcept {
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
  apply_law(solution, constants, history, cache);
  return solution;
}

[[nodiscard]] inline PairSolution sphere_wall(const BodyRef& body, const WallPlane& wall, ContactHistory& history,
                                              ContactCache& cache, const InteractionContext& context) noexcept {
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
  apply_law(solution, constants, history, cache);
  return solution;
}

}  // namespace pair_detail

// Two bodies; `spheres` selects the closed-form path. Reads and updates the history's warm
// start; on contact stores the law's new δ_* in the history and δ in the cache.
[[nodiscard]] inline PairSolution solve_pair(const BodyRef& body_i, const BodyRef& body_j, bool spheres,
                                             ContactHistory& history, ContactCache& cache,
                                             const InteractionContext& context) noexcept {
  if (spheres) return pair_detail::sphere_pair(body_i, body_j, history, cache, context);
  return solve_ellipsoid_pair(body_i, body_j, history, cache, context);
}

// A body against a wall, mirror-image convention: r̂^{I,J} = 2 r̂^I, the wall flat (κ = 0).
[[nodiscard]] inline PairSolution solve_wall(const BodyRef& body, const WallPlane& wall, bool sphere,
                                             ContactHistory& history, ContactCache& cache,
                                             const InteractionContext& context) noexcept {
  if (sphere) return pair_detail::sphere_wall(body, wall, history, cache, context);
  return solve_ellipsoid_wall(body, wall, history, cache, context);
}

// Forces of a touching contact (solution.status == contact) on both bodies; `centre_j` is J's
// (image) centre. Updates the history's tangential spring.
[[nodiscard]] inline PairForces pair_forces(const PairSolution& solution, const Eigen::Vector3d& centre_i,
                                            const BodyMotion& motion_i, const Eigen::Vector3d& centre_j,
                                            const BodyMotion& motion_j, const InteractionContext& context, double dt,
                                            ContactHistory& history) noexcept {
  const Eigen::Vector3d lever_i = solution.point - centre_i;
  const Eigen::Vector3d lever_j = solution.point - centre_j;
  const ContactKinematics kinematics{solution.normal,
                                     motion_j.velocity + motion_j.angular_velocity.cross(lever_j) - motion_i.velocity -
                                         motion_i.angular_velocity.cross(lever_i),
                                     motion_i.mass * motion_j.mass / (motion_i.mass + motion_j.mass)};
  // The contact force built in place (assigned to a default PairForces, it was built, then copied).
  PairForces forces{
      contact_force(context, *solution.constants, solution.law.force, solution.branch, kinematics, dt, history)};
  forces.torque_on_i = -lever_i.cross(forces.contact.on_j);
  forces.torque_on_j = lever_j.cross(forces.contact.on_j);
  return forces;
}

// A touching body–wall contact; the wall moves along z at `wall_velocity` and does not turn.
[[nodiscard]] inline WallForces wall_forces(const PairSolution& solution, const Eigen::Vector3d& centre,
                                            const BodyMotion& motion, double wall_velocity,
                                            const InteractionContext& context, double dt,
                                            ContactHistory& history) noexcept {
  const Eigen::Vector3d lever = solution.point - centre;
  const ContactKinematics kinematics{
      solution.normal,
      Eigen::Vector3d(0.0, 0.0, wall_velocity) - motion.velocity - motion.angular_velocity.cross(lever), motion.mass};
  WallForces forces{
      contact_force(context, *solution.constants, solution.law.force, solution.branch, kinematics, dt, history)};
  forces.lever_cross_force = lever.cross(forces.contact.on_j);
  return forces;
}

}  // namespace ellc
