#pragma once
// Contact response on top of the normal law: viscous normal damping, Mindlin-type tangential
// spring with Coulomb friction, and the energy bookkeeping of the law force.
//
//  * Normal: F_n = max(0, F_law − c_n v_n), c_n = 2 ζ sqrt(m* k_n), k_n = 2 E_e c_c
//    (the Hertz tangent stiffness at the equivalent contact radius c_c of eq. 9).
//  * Tangential: ξ += v_t dt on the current tangent plane (rotated, magnitude kept),
//    F_t = −k_t ξ − c_t v_t, k_t = 8 G_e c_c (Mindlin), c_t = 2 ζ sqrt(m* k_t),
//    |F_t| ≤ µ F_n; when sliding, ξ is reset to −(F_t + c_t v_t)/k_t.
//  * Only the stiffnesses are chosen here: the damped normal force and the tangential spring
//    are src/ellc/response/ (normal_damping.hpp, tangential_spring.hpp), shared with LAMMPS.
//  * F_law is the Becker–Kamlah force from evaluate_contact(), used unchanged.
//  * Energy: plastic_work() of δ_* per contact (dissipated for good), recoverable_energy() of
//    (δ, δ_*) for what is stored elastically.

#include <Eigen/Core>

#include "ellc/engine/contact_history.hpp"
#include "ellc/law/contact_law.hpp"

namespace ellc::engine {

struct ResponseParameters {
  double shear_modulus = 0.0;  // G_e = [ (2 − ν_I)/G_I + (2 − ν_J)/G_J ]⁻¹
  double damping_ratio = 0.0;  // ζ
  double friction = 0.0;       // µ
  double dt = 0.0;
};

struct ContactKinematics {
  Eigen::Vector3d normal;             // unit, I → J
  Eigen::Vector3d relative_velocity;  // of J's material point relative to I's, at the contact point
  double effective_mass = 0.0;        // m_I m_J / (m_I + m_J); m_I against a wall
};

// Total force on J (normal + tangential). Updates `history.tangential_spring`.
[[nodiscard]] Eigen::Vector3d contact_response(const ContactKinematics& kinematics, const ContactConstants& constants,
                                               double overlap, double law_force, const ResponseParameters& parameters,
                                               ContactHistory& history) noexcept;

// Elastic energy the law gives back on full unloading from (δ, δ_*): ∫ F dδ along the
// unloading branch (eq. 49) or along Hertz (eq. 10) when the contact never yielded.
[[nodiscard]] double recoverable_energy(const ContactConstants& constants, double overlap, double max_overlap) noexcept;

// Energy the law has dissipated plastically in a contact with history δ_*: the area between the
// loading curve and the unloading branch, ∫₀^δ* F_load dδ − ∫_δp^δ* F_UL dδ (0 while δ_* ≤ δ_Y).
// Depends on δ_* only, so purely elastic contacts dissipate exactly nothing, whatever the
// geometry does. Hertz part in closed form, the plastic part by Simpson's rule.
[[nodiscard]] double plastic_work(const ContactConstants& constants, double max_overlap) noexcept;

// Clears a history on separation; returns its plastic work, which the caller books as dissipated.
// Keeps what is not contact history: cached sphere constants and the narrow-phase warm start
// (the separating axis, tested first next step).
double clear_history(ContactHistory& history) noexcept;

}  // namespace ellc::engine
