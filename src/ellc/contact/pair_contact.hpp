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

// Two bodies; `spheres` selects the closed-form path. Reads and updates the history's warm
// start; on contact stores the law's new δ_* in the history and δ in the cache.
[[nodiscard]] PairSolution solve_pair(const BodyRef& body_i, const BodyRef& body_j, bool spheres,
                                      ContactHistory& history, ContactCache& cache,
                                      const InteractionContext& context) noexcept;

// A body against a wall, mirror-image convention: r̂^{I,J} = 2 r̂^I, the wall flat (κ = 0).
[[nodiscard]] PairSolution solve_wall(const BodyRef& body, const WallPlane& wall, bool sphere, ContactHistory& history,
                                      ContactCache& cache, const InteractionContext& context) noexcept;

// The ellipsoid paths (pair_contact_ellipsoids.cpp), called by the two functions above.
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

// Forces of a touching contact (solution.status == contact) on both bodies; `centre_j` is J's
// (image) centre. Updates the history's tangential spring.
[[nodiscard]] PairForces pair_forces(const PairSolution& solution, const Eigen::Vector3d& centre_i,
                                     const BodyMotion& motion_i, const Eigen::Vector3d& centre_j,
                                     const BodyMotion& motion_j, const InteractionContext& context, double dt,
                                     ContactHistory& history) noexcept;

struct WallForces {
  ContactForce contact;  // contact.on_j: the force on the wall; the force on the body is −contact.on_j
  Eigen::Vector3d lever_cross_force = Eigen::Vector3d::Zero();  // (x − c) × contact.on_j: −torque on the body
};

// A touching body–wall contact; the wall moves along z at `wall_velocity` and does not turn.
[[nodiscard]] WallForces wall_forces(const PairSolution& solution, const Eigen::Vector3d& centre,
                                     const BodyMotion& motion, double wall_velocity, const InteractionContext& context,
                                     double dt, ContactHistory& history) noexcept;

}  // namespace ellc
