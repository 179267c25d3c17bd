#include "ellc/contact/contact_model.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <tuple>
#include <utility>

#include "ellc/contact/contact_parameters.hpp"
#include "ellc/contact/normal_damping.hpp"
#include "ellc/contact/tangential_spring.hpp"
#include "ellc/law/contact_law.hpp"

namespace ellc {

namespace {

template <typename Model, std::size_t N>
using NameTable = std::array<std::pair<Model, std::string_view>, N>;

constexpr NameTable<NormalModel, 2> kNormalNames{
    {{NormalModel::becker_kamlah, "becker_kamlah"}, {NormalModel::hertz, "hertz"}}};
constexpr NameTable<DampingModel, 2> kDampingNames{
    {{DampingModel::contact_radius, "contact_radius"}, {DampingModel::hertz_tangent, "hertz_tangent"}}};
constexpr NameTable<TangentialModel, 2> kTangentialNames{
    {{TangentialModel::mindlin, "mindlin"}, {TangentialModel::ratio, "ratio"}}};

template <typename Model, std::size_t N>
std::string_view lookup_name(const NameTable<Model, N>& table, Model model) noexcept {
  for (const auto& [value, name] : table)
    if (value == model) return name;
  return "unknown";
}

template <typename Model, std::size_t N>
std::optional<Model> lookup_model(const NameTable<Model, N>& table, std::string_view name) noexcept {
  for (const auto& [value, entry] : table)
    if (entry == name) return value;
  return std::nullopt;
}

template <typename Model, std::size_t N>
std::string joined_names(const NameTable<Model, N>& table) {
  std::string text;
  for (std::size_t k = 0; k < N; ++k) {
    if (k > 0) text += k + 1 == N ? " or " : ", ";
    text += table[k].second;
  }
  return text;
}

// Mindlin's G_e = [ (2 − ν_I)/G_I + (2 − ν_J)/G_J ]⁻¹; for one material G/(2(2 − ν)).
double effective_shear_modulus(const Material& body_i, const Material& body_j) noexcept {
  const auto shear = [](const Material& m) { return m.youngs_modulus / (2.0 * (1.0 + m.poisson_ratio)); };
  if (body_i.youngs_modulus == body_j.youngs_modulus && body_i.poisson_ratio == body_j.poisson_ratio)
    return shear(body_i) / (2.0 * (2.0 - body_i.poisson_ratio));
  return 1.0 / ((2.0 - body_i.poisson_ratio) / shear(body_i) + (2.0 - body_j.poisson_ratio) / shear(body_j));
}

// The contact's size and the normal stiffness the dashpot (and the ratio spring) scale with, on
// the elastic branch the contact is on (law/contact_law.hpp, ElasticBranch).
struct BranchStiffness {
  double contact_radius = 0.0;  // c, eq. (9) with the branch's radius
  double normal = 0.0;          // k_n
};

BranchStiffness branch_stiffness(DampingModel model, const ContactConstants& constants,
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

}  // namespace

std::string_view name_of(NormalModel model) noexcept { return lookup_name(kNormalNames, model); }
std::string_view name_of(DampingModel model) noexcept { return lookup_name(kDampingNames, model); }
std::string_view name_of(TangentialModel model) noexcept { return lookup_name(kTangentialNames, model); }
std::optional<NormalModel> normal_model_named(std::string_view name) noexcept {
  return lookup_model(kNormalNames, name);
}
std::optional<DampingModel> damping_model_named(std::string_view name) noexcept {
  return lookup_model(kDampingNames, name);
}
std::optional<TangentialModel> tangential_model_named(std::string_view name) noexcept {
  return lookup_model(kTangentialNames, name);
}
std::string normal_model_names() { return joined_names(kNormalNames); }
std::string damping_model_names() { return joined_names(kDampingNames); }
std::string tangential_model_names() { return joined_names(kTangentialNames); }

std::string validation_error(const ContactModel& model, std::string_view where) {
  const auto text = [](double value) {  // shortest round-trip form: 1e+300, not 301 digits
    char buffer[32];
    return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr);
  };
  for (const auto& [name, value] :
       {std::pair{"normal_damping", model.normal_damping}, std::pair{"tangential_damping", model.tangential_damping}})
    if (!(value >= 0.0 && value < 1.0))
      return std::string(where) + "." + name + " = " + text(value) + ": expected a damping ratio in [0, 1)";
  const std::tuple<const char*, double, double> bounded[] = {
      {"friction", model.friction, kMaxFriction},
      {"tangential_stiffness", model.tangential_stiffness_ratio, kMaxTangentialStiffnessRatio}};
  for (const auto& [name, value, largest] : bounded)
    if (!(std::isfinite(value) && value >= 0.0 && value <= largest))
      return std::string(where) + "." + name + " = " + text(value) + ": expected a finite number in [0, " +
             text(largest) + "]";
  if (!(model.narrow_phase_final_step > 0.0 && model.narrow_phase_final_step <= 0.1))
    return std::string(where) + ".narrow_phase_final_step = " + text(model.narrow_phase_final_step) +
           ": expected a Newton step length in (0, 0.1] rad";
  if (std::string error = validation_error(model.law); !error.empty()) return error;
  return {};
}

InteractionContext make_interaction(const ContactModel& model, const Material& body_i,
                                    const Material& body_j) noexcept {
  InteractionContext context;
  context.model = model;
  context.material = mix(body_i, body_j);
  // Plain Hertz is the same law with a yield stress it never reaches (δ_Y ≫ any overlap).
  if (model.normal == NormalModel::hertz) context.material.yield_stress = 1e30;
  context.shear_modulus = effective_shear_modulus(body_i, body_j);
  context.narrow_phase.final_step = model.narrow_phase_final_step;
  context.narrow_phase.surface_curvatures = false;  // the law needs A and B only
  return context;
}

namespace {
double tangential_stiffness(const InteractionContext& context, const BranchStiffness& branch) noexcept {
  return context.model.tangential == TangentialModel::mindlin
             ? 8.0 * context.shear_modulus * branch.contact_radius
             : context.model.tangential_stiffness_ratio * branch.normal;
}
}  // namespace

ContactForce contact_force(const InteractionContext& context, const ContactConstants& constants, double law_force,
                           const ElasticBranch& elastic, const ContactKinematics& kinematics, double dt,
                           ContactHistory& history) noexcept {
  const ContactModel& model = context.model;
  const Eigen::Vector3d& n = kinematics.normal;
  const BranchStiffness branch = branch_stiffness(model.damping, constants, elastic);
  const double normal_speed = kinematics.relative_velocity.dot(n);  // > 0 when separating
  const double normal_force = damped_normal_force(
      law_force, viscous_damping(model.normal_damping, kinematics.effective_mass, branch.normal), normal_speed);

  ContactForce result;
  result.normal_stiffness = branch.normal;
  result.damping_dissipation = (law_force - normal_force) * normal_speed * dt;
  const double k_t = tangential_stiffness(context, branch);
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
      tangential_response(spring, n, kinematics.relative_velocity, dt, normal_force, tangential);
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
