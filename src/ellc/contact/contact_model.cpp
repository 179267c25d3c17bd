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

}  // namespace ellc
