#pragma once
// pair_style ellipsoid/bk's view of one pair, free of LAMMPS types so it can be unit-tested: the
// shared contact model (src/ellc/contact/pair_contact.hpp) on LAMMPS's atoms and its history
// record stored as raw doubles. Nothing here computes a force; the physics is the same code the
// built-in engine runs.
//
// Canonical orientation: body "a" is the atom with the lower ID, body "b" the higher; the normal
// points from a to b and the history is stored in that frame. The result is therefore the same
// whichever atom of the pair a neighbor list (or an MPI rank) puts first.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "ellc/contact/contact_history.hpp"
#include "ellc/contact/contact_model.hpp"
#include "ellc/geometry/ellipsoid.hpp"
#include "ellc/law/contact_law.hpp"

namespace ellc_lammps {

// Doubles per contact in the history fix: exactly the shared record.
inline constexpr int kHistoryDoubles = static_cast<int>(ellc::ContactHistory::kDoubles);

struct BodyState {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d semi_axes = Eigen::Vector3d::Ones();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  // body frame → space frame
  double mass = 1.0;
};

// The posed ellipsoid and its mean radius r̂, built by the caller once per atom and step, with
// the atom's motion (velocity, angular velocity and mass are read from it).
struct AtomBody {
  const ellc::Ellipsoid& ellipsoid;
  double mean_radius;
  const BodyState& motion;
};

struct PairEvaluation {
  bool touching = false;
  bool geometry_failed = false;  // the narrow phase could not resolve the pair (invalid bodies)
  int iterations = 0;            // narrow-phase Newton steps
  bool keep_warm_start = false;  // not touching, but the history holds a separating axis to reuse
  // Not touching: solve_pair's clearance (PairSolution::clearance): while the two bodies' points
  // move less than this in total, evaluating the pair again would change nothing. 0 = unknown.
  double clearance = 0.0;
  double overlap = 0.0;
  double normal_force = 0.0;  // the law's force with damping, ≥ 0
  ellc::LawResult law;
  double contact_radius_sq_per_overlap = 0.0;        // c_c² / δ_* of the contact constants (c_c/r̂ output)
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  // a → b
  Eigen::Vector3d point = Eigen::Vector3d::Zero();   // where the force acts
  Eigen::Vector3d force_on_b = Eigen::Vector3d::Zero();
  Eigen::Vector3d torque_on_a = Eigen::Vector3d::Zero();
  Eigen::Vector3d torque_on_b = Eigen::Vector3d::Zero();
};

// Evaluates the contact and updates `history` (kHistoryDoubles doubles, zero for a new pair).
// When the bodies do not overlap the contact ends (δ_* and the spring are zeroed) and only the
// narrow phase's separating axis may be kept (keep_warm_start). A failed narrow phase leaves the
// history as it was, as in the built-in engine.
// `scratch` holds the contact constants while the result is built; its contents on entry do not
// matter (a caller evaluating many pairs passes one object, saving its construction per pair).
[[nodiscard]] PairEvaluation evaluate_pair(const AtomBody& a, const AtomBody& b,
                                           const ellc::InteractionContext& context, double timestep, double* history,
                                           ellc::ContactCache& scratch);

// The same, posing the bodies from their states (tests, one-off evaluations).
[[nodiscard]] PairEvaluation evaluate_pair(const BodyState& a, const BodyState& b,
                                           const ellc::InteractionContext& context, double timestep, double* history);

}  // namespace ellc_lammps
