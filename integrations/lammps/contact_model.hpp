#pragma once
// The per-pair physics of pair ellipsoid/bk, free of LAMMPS types so it can be unit-tested:
// narrow phase (the project's geometry layer) → Becker–Kamlah normal force (the project's law,
// unchanged) + normal damping + tangential Coulomb friction with a history spring (both the
// project's src/ellc/response, shared with the DEM engine; only the stiffnesses are chosen here).
//
// Canonical orientation: body "a" is the atom with the lower ID, body "b" the higher; the normal
// points from a to b and the history is stored in that frame. The result is therefore the same
// whichever atom of the pair a neighbor list (or an MPI rank) puts first.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "ellc/geometry/narrow_phase.hpp"
#include "ellc/hertz/elliptic_hertz.hpp"
#include "ellc/law/contact_law.hpp"
#include "ellc/law/transition_fit.hpp"
#include "ellc/material/material.hpp"

namespace ellc_lammps {

// What a pair of atom types needs (pair_coeff, after mixing).
struct PairCoefficients {
  ellc::ContactMaterial material;     // E_e (eq. 3) and Y (model-notes §5)
  double friction = 0.0;              // μ, Coulomb limit |F_t| ≤ μ F_n
  double normal_damping = 0.0;        // η_n: F_d = −2 η_n sqrt(m_eff k_n) v_n
  double tangential_damping = 0.0;    // η_t: −2 η_t sqrt(m_eff k_t) v_t
  double tangential_stiffness = 1.0;  // k_t / k_n
  ellc::LawParameters law;
};

struct BodyState {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d semi_axes = Eigen::Vector3d::Ones();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  // body frame → space frame
  double mass = 1.0;
};

// Layout of one contact's history (doubles): δ_*, the tangential spring (3), then the
// narrow-phase warm start (the last common normal and whether it is set).
struct HistoryLayout {
  static constexpr int max_overlap = 0;
  static constexpr int spring = 1;
  static constexpr int warm_normal = 4;
  static constexpr int warm_valid = 7;
  [[nodiscard]] static constexpr int size() { return 8; }
};

struct PairResult {
  bool touching = false;
  bool geometry_failed = false;  // the narrow phase could not resolve the pair (invalid bodies)
  int iterations = 0;            // narrow-phase Newton steps
  bool keep_warm_start = false;  // not touching, but the history holds a separating axis to reuse
  double overlap = 0.0;
  double normal_force = 0.0;  // elastoplastic law + damping, ≥ 0
  ellc::LawResult law;
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  // a → b
  Eigen::Vector3d point = Eigen::Vector3d::Zero();   // where the force acts
  Eigen::Vector3d force_on_b = Eigen::Vector3d::Zero();
  Eigen::Vector3d torque_on_a = Eigen::Vector3d::Zero();
  Eigen::Vector3d torque_on_b = Eigen::Vector3d::Zero();
};

// Evaluates the contact and updates `history` (HistoryLayout::size() doubles, zero for a new
// pair). When the bodies do not overlap, δ_* and the spring are zeroed (model-notes §5),
// touching=false, and only the narrow phase's separating axis may be kept (keep_warm_start).
[[nodiscard]] PairResult evaluate_pair(const BodyState& a, const BodyState& b, const PairCoefficients& coefficients,
                                       ellc::HertzMode mode, double timestep, double* history);

// The same with the posed ellipsoids and their mean radii r̂ built by the caller (once per atom
// and step in the pair style). Only velocity, angular_velocity and mass are read from the states.
struct PosedBody {
  const ellc::Ellipsoid& ellipsoid;
  double mean_radius;
  const BodyState& motion;
};
[[nodiscard]] PairResult evaluate_pair(const PosedBody& a, const PosedBody& b, const PairCoefficients& coefficients,
                                       ellc::HertzMode mode, double timestep, double* history);

// ω = R I⁻¹ Rᵀ L for a solid ellipsoid of mass m and semi-axes (a, b, c).
[[nodiscard]] Eigen::Vector3d angular_velocity(const Eigen::Vector3d& angular_momentum,
                                               const Eigen::Quaterniond& orientation,
                                               const Eigen::Vector3d& semi_axes, double mass);

}  // namespace ellc_lammps
