#pragma once
// The force of one touching contact under the shared contact model (contact_model.hpp): the law's
// force, the dashpot and the Coulomb-limited tangential spring, with the energy each dissipative
// part took. Both engines reach it through pair_forces() / wall_forces() (pair_contact.hpp).
// Header-only and inline: it runs once per contact and step, and a call across translation units
// kept its inputs and its result in memory (12 % more instructions per sphere contact).

#include <Eigen/Core>

#include <algorithm>
#include <cmath>

#include "ellc/contact/contact_history.hpp"
#include "ellc/contact/contact_model.hpp"
#include "ellc/contact/normal_damping.hpp"
#include "ellc/contact/tangential_spring.hpp"
#include "ellc/law/contact_constants.hpp"
#include "ellc/law/contact_law.hpp"

namespace ellc {

namespace contact_detail {
// The contact's size and the normal stiffness the dashpot (and the ratio spring) scale with, on
// the elastic branch the contact is on (law/contact_law.hpp, ElasticBranch).
struct BranchStiffness {
  double contact_radius = 0.0;  // c, eq. (9) with the branch's radius
  double normal = 0.0;          // k_n
};

inline BranchStiffness branch_stiffness(DampingModel model, const ContactConstants& constants,
                                        const ElasticBranch& branch) noexcept {
  const double x = std::max(branch.elastic_overlap, 0.0);
  BranchStiffness stiffness;
  stiffness.contact_radius = branch.radius_scale == 1.0
                                 ? std::sqrt(constants.contact_radius_sq_per_overlap * x)
                                 : std::sqrt(constants.contact_radius_sq_per_overlap * branch.radius_scale * x);
  stiffness.normal = model == DampingModel::hertz_tangent
                         ? 1.5 * branch.coefficient * std::sqrt(x)
                         : 2.0 * constants.effective_modulus * stiffness.contact_radius;
  return stiffness;
}

inline double tangential_stiffness(const InteractionContext& context, const BranchStiffness& branch) noexcept {
  return context.model.tangential == TangentialModel::mindlin
             ? 8.0 * context.shear_modulus * branch.contact_radius
             : context.model.tangential_stiffness_ratio * branch.normal;
}
}  // namespace contact_detail

// Force on J of one touching contact whose law force F_law = law_force was evaluated with
// `constants` on the elastic branch `elastic` (both from evaluate_contact_on_branch). Updates the
// history's tangential spring (δ_* is the caller's, from the law's result).
[[nodiscard]] inline ContactForce contact_force(const InteractionContext& context, const ContactConstants& constants,
                                                double law_force, const ElasticBranch& elastic,
                                                const ContactKinematics& kinematics, double dt,
                                                ContactHistory& history) noexcept {
  const ContactModel& model = context.model;
  const Eigen::Vector3d& n = kinematics.normal;
  const contact_detail::BranchStiffness branch = contact_detail::branch_stiffness(model.damping, constants, elastic);
  const double normal_speed = kinematics.relative_velocity.dot(n);  // > 0 when separating
  const double normal_force = damped_normal_force(
      law_force, viscous_damping(model.normal_damping, kinematics.effective_mass, branch.normal), normal_speed);

  ContactForce result;
  result.normal_stiffness = branch.normal;
  result.damping_dissipation = (law_force - normal_force) * normal_speed * dt;
  const double k_t = contact_detail::tangential_stiffness(context, branch);
  if (!(k_t > 0.0) || !(model.friction > 0.0)) {            // no spring: c_t is not needed
    result.friction_dissipation = history.spring_energy();  // what a spring of the last step still held
    history.spring() = Eigen::Vector3d::Zero();
    history.spring_stiffness = k_t;
    result.on_j = normal_force * n;
    return result;
  }
  const TangentialCoefficients tangential{
      k_t, viscous_damping(model.tangential_damping, kinematics.effective_mass, k_t), model.friction};
  // Incremental spring (Thornton and Yin): a stiffer contact keeps the spring's force (ξ scaled by
  // k_old/k_t), a softer one keeps ξ so the force shrinks with the contact. Either way the spring
  // gives up energy, never gains it; what it gives up is booked with friction. The loss of an
  // overlap cycle is of the order of k_t's change over it; it stays small because k_t is continuous
  // where the contact turns from loading to unloading (law/contact_law.hpp, top_of_unloading_branch).
  const double k_old = history.spring_stiffness;
  Eigen::Vector3d spring = carry_to_tangent_plane(history.spring(), n);  // its length kept: no work
  const double energy_before = 0.5 * (k_old > 0.0 ? k_old : k_t) * spring.squaredNorm();
  if (k_old > 0.0 && k_t > k_old) spring *= k_old / k_t;
  const double released = energy_before - 0.5 * k_t * spring.squaredNorm();
  const TangentialResponse friction =
      tangential_response_on_plane(spring, n, kinematics.relative_velocity, dt, normal_force, tangential);
  history.spring() = friction.spring;
  history.spring_stiffness = k_t;
  result.on_j = normal_force * n + friction.force;

  // Energy: what the dissipative forces took from the relative motion over this step.
  const Eigen::Vector3d tangential_velocity = kinematics.relative_velocity - normal_speed * n;
  const double tangential_work = -friction.force.dot(tangential_velocity) * dt;
  const double stored = 0.5 * k_t * (friction.spring.squaredNorm() - spring.squaredNorm());
  const double dashpot = friction.sliding ? 0.0 : tangential.damping * tangential_velocity.squaredNorm() * dt;
  result.damping_dissipation += dashpot;
  result.friction_dissipation = tangential_work - stored - dashpot + released;
  return result;
}

}  // namespace ellc
