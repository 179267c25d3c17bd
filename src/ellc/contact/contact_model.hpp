#pragma once
// The contact model both engines run: named sub-models behind one value type, in the manner of
// LAMMPS's granular model (normal, damping, tangential), and the force of one touching contact.
// The built-in engine (src/ellc/engine/simulation.cpp) and pair_style ellipsoid/bk
// (integrations/lammps/pair_ellipsoid_bk.cpp) both call pair_forces() / wall_forces() (pair_contact.hpp),
// which call contact_force() (contact_force.hpp), so a
// study moves between them with the same physics. docs/contact_model.md documents every sub-model.
//
//  normal      becker_kamlah   the elastoplastic law, evaluate_contact() (src/ellc/law/contact_law.hpp)
//              hertz           the same law with a yield stress it never reaches (purely elastic)
//  damping     contact_radius  c = 2 ζ sqrt(m* k), k_n = 2 E_e c: the Hertz tangent stiffness
//                              written with the contact radius c of eq. (9) on the current branch
//              hertz_tangent   the same with k_n = 3/2 C x^{1/2}, the tangent of the branch F = C x^{3/2}
//  Branch (law/contact_law.hpp, ElasticBranch): Hertz until the contact yields; then the unloading
//  curve (eq. 49) with R_e,pmax and x = δ − δ_p, below δ_* and, at its top, while loading.
//  tangential  mindlin         k_t = 8 G_e c_c,  G_e = [ (2 − ν_I)/G_I + (2 − ν_J)/G_J ]⁻¹
//              ratio           k_t = κ k_n, k_n of the damping sub-model
// Then F_n = max(0, F_law − c_n v_n) and the Coulomb-limited spring (tangential_spring.hpp), with
// c_t = 2 ζ_t sqrt(m* k_t), updated incrementally: when k_t grows the spring keeps its force.

#include <Eigen/Core>

#include <optional>
#include <string>
#include <string_view>

#include "ellc/contact/contact_history.hpp"
#include "ellc/geometry/narrow_phase.hpp"
#include "ellc/hertz/elliptic_hertz.hpp"
#include "ellc/law/contact_constants.hpp"
#include "ellc/law/contact_law.hpp"
#include "ellc/law/transition_fit.hpp"
#include "ellc/material/material.hpp"

namespace ellc {

enum class NormalModel { becker_kamlah, hertz };
enum class DampingModel { contact_radius, hertz_tangent };
enum class TangentialModel { mindlin, ratio };

[[nodiscard]] std::string_view name_of(NormalModel model) noexcept;
[[nodiscard]] std::string_view name_of(DampingModel model) noexcept;
[[nodiscard]] std::string_view name_of(TangentialModel model) noexcept;
[[nodiscard]] std::optional<NormalModel> normal_model_named(std::string_view name) noexcept;
[[nodiscard]] std::optional<DampingModel> damping_model_named(std::string_view name) noexcept;
[[nodiscard]] std::optional<TangentialModel> tangential_model_named(std::string_view name) noexcept;
// "becker_kamlah or hertz", for error messages.
[[nodiscard]] std::string normal_model_names();
[[nodiscard]] std::string damping_model_names();
[[nodiscard]] std::string tangential_model_names();

// The sub-models and their parameters. The values here are the model's neutral defaults (no
// damping, no friction); each engine's input documents its own defaults for ζ and μ.
struct ContactModel {
  NormalModel normal = NormalModel::becker_kamlah;
  HertzMode hertz = HertzMode::hale;
  LawParameters law;
  DampingModel damping = DampingModel::contact_radius;
  double normal_damping = 0.0;      // ζ_n
  double tangential_damping = 0.0;  // ζ_t
  TangentialModel tangential = TangentialModel::mindlin;
  double tangential_stiffness_ratio = 1.0;  // κ = k_t / k_n (ratio only)
  double friction = 0.0;                    // μ, |F_t| ≤ μ F_n
  // Ellipsoid pairs: a Newton step of the common normal shorter than this (rad) ends the solve
  // (NarrowPhaseOptions). 1e-9 solves to rounding; 1e-3, one step per time step from the warm start.
  double narrow_phase_final_step = 1e-9;
};

// Empty when the model can be used; otherwise a sentence naming the parameter (prefixed by
// `where`, e.g. "[contact]"), its value and what was expected.
[[nodiscard]] std::string validation_error(const ContactModel& model, std::string_view where);

// Everything one kind of interaction (particle–particle, particle–wall, a pair of LAMMPS types)
// needs, built once from the model and the two materials.
struct InteractionContext {
  ContactModel model;
  ContactMaterial material;    // E_e (eq. 3) and Y = min(Y_I, Y_J); Y out of reach for hertz
  double shear_modulus = 0.0;  // G_e (mindlin)
  NarrowPhaseOptions narrow_phase;
};

[[nodiscard]] InteractionContext make_interaction(const ContactModel& model, const Material& body_i,
                                                  const Material& body_j) noexcept;

struct ContactKinematics {
  Eigen::Vector3d normal;             // unit, I → J
  Eigen::Vector3d relative_velocity;  // of J's material point relative to I's, at the contact point
  double effective_mass = 0.0;        // m_I m_J / (m_I + m_J); m_I against a wall
};

// The force of one contact and the energy its dissipative parts took over the step of length dt
// in which the bodies moved with the kinematics' relative velocity.
struct ContactForce {
  Eigen::Vector3d on_j = Eigen::Vector3d::Zero();
  double damping_dissipation =
      0.0;  // normal dashpot −(F_n − F_law) v_n dt ≥ 0, tangential c_t |v_t|² dt while sticking
  double friction_dissipation =
      0.0;  // tangential work not kept by the spring (sliding): −F_t·v_t dt − ΔE_spring − the above
  double normal_stiffness = 0.0;  // k_n of the damping sub-model on the current branch: a plate
                                  // servo's loop gain (engine/servo.hpp) sums it over the plate
};

// contact_force(), the force of one touching contact under this model: contact_force.hpp.

}  // namespace ellc
