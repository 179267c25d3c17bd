#include "ellc/contact/contact_parameters.hpp"

#include <cmath>

namespace ellc {

const ContactParameterName* find_contact_parameter(std::string_view name) noexcept {
  for (const ContactParameterName& entry : kContactParameters)
    if (entry.name == name) return &entry;
  return nullptr;
}

std::string ContactModelBuilder::set(std::string_view name, std::string_view choice) {
  if (name == "normal") {
    if (const auto model = normal_model_named(choice)) {
      model_.normal = *model;
      return {};
    }
    return normal_model_names();
  }
  if (name == "damping_model") {
    if (const auto model = damping_model_named(choice)) {
      model_.damping = *model;
      return {};
    }
    return damping_model_names();
  }
  if (name == "tangential_model") {
    if (const auto model = tangential_model_named(choice)) {
      model_.tangential = *model;
      tangential_model_given_ = true;
      return {};
    }
    return tangential_model_names();
  }
  return find_contact_parameter(name) != nullptr ? "a number" : "a contact-model parameter";
}

std::string ContactModelBuilder::set(std::string_view name, double value) {
  const bool finite = std::isfinite(value);
  if (name == "damping_ratio" || name == "normal_damping" || name == "tangential_damping") {
    // ζ ≥ 1 is an overdamped contact, which no DEM calibration wants and which hides rate effects.
    if (!(finite && value >= 0.0 && value < 1.0)) return "a damping ratio in [0, 1)";
    if (name != "tangential_damping") model_.normal_damping = value;
    if (name != "normal_damping") model_.tangential_damping = value;
    return {};
  }
  if (name == "tangential_stiffness") {
    if (!(finite && value >= 0.0 && value <= kMaxTangentialStiffnessRatio))
      return "a stiffness ratio k_t / k_n in [0, 1.5] (Mindlin's 2(1-nu)/(2-nu) stays below 4/3 for every "
             "admissible nu; far above it the time step, set by k_n, no longer holds)";
    model_.tangential_stiffness_ratio = value;
    tangential_stiffness_given_ = true;
    return {};
  }
  if (name == "friction") {
    if (!(finite && value >= 0.0 && value <= kMaxFriction))
      return "a friction coefficient in [0, 10] (measured ones are below ~2; more only stops sliding)";
    model_.friction = value;
    return {};
  }
  if (name == "narrow_phase_final_step") {
    if (!(finite && value > 0.0 && value <= 0.1))
      return "a Newton step length in (0, 0.1] rad (1e-9 solves the common normal to rounding)";
    model_.narrow_phase_final_step = value;
    return {};
  }
  return find_contact_parameter(name) != nullptr ? "one of its names, not a number" : "a contact-model parameter";
}

ContactModel ContactModelBuilder::finish() const {
  ContactModel model = model_;
  if (tangential_stiffness_given_ && !tangential_model_given_) model.tangential = TangentialModel::ratio;
  return model;
}

}  // namespace ellc
