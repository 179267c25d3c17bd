#pragma once
// The names of the contact model's parameters, one vocabulary for both inputs: the [contact]
// table of an `ellc dem` scenario and the keywords of LAMMPS's pair_coeff. Each reader only
// splits its own syntax into (name, value) and hands them here; the meaning of a name, its
// range and its error message exist once (docs/contact_model.md lists them).
//
//   normal                 becker_kamlah | hertz
//   damping_model          contact_radius | hertz_tangent
//   damping_ratio          ζ of both dashpots, [0, 1)
//   normal_damping         ζ_n, [0, 1)
//   tangential_damping     ζ_t, [0, 1)
//   tangential_model       mindlin | ratio
//   tangential_stiffness   κ = k_t/k_n ≥ 0 (selects ratio unless tangential_model is given)
//   friction               μ ≥ 0
//   narrow_phase_final_step  (0, 0.1] rad

#include <array>
#include <string>
#include <string_view>

#include "ellc/contact/contact_model.hpp"

namespace ellc {

enum class ParameterKind { choice, number };

struct ContactParameterName {
  std::string_view name;
  ParameterKind kind;
};

inline constexpr std::array<ContactParameterName, 9> kContactParameters{{
    {"normal", ParameterKind::choice},
    {"damping_model", ParameterKind::choice},
    {"damping_ratio", ParameterKind::number},
    {"normal_damping", ParameterKind::number},
    {"tangential_damping", ParameterKind::number},
    {"tangential_model", ParameterKind::choice},
    {"tangential_stiffness", ParameterKind::number},
    {"friction", ParameterKind::number},
    {"narrow_phase_final_step", ParameterKind::number},
}};

// Upper bounds both engines enforce (docs/input_limits.md): κ = k_t/k_n, Mindlin's
// 2(1−ν)/(2−ν) < 4/3 for every −1 < ν < 0.5, with some room; and μ.
inline constexpr double kMaxTangentialStiffnessRatio = 1.5;
inline constexpr double kMaxFriction = 10.0;

[[nodiscard]] const ContactParameterName* find_contact_parameter(std::string_view name) noexcept;

// Collects named parameters into a model. Each set() returns an empty string when the value was
// accepted, else what was expected (the caller adds the field and the value it was given).
class ContactModelBuilder {
 public:
  explicit ContactModelBuilder(ContactModel start) : model_(start) {}

  [[nodiscard]] std::string set(std::string_view name, std::string_view choice);
  [[nodiscard]] std::string set(std::string_view name, double value);
  // The model, with tangential_stiffness implying the ratio model when tangential_model was not given.
  [[nodiscard]] ContactModel finish() const;

 private:
  ContactModel model_;
  bool tangential_model_given_ = false;
  bool tangential_stiffness_given_ = false;
};

}  // namespace ellc
