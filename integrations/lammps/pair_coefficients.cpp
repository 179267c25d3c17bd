#include "pair_coefficients.hpp"

#include <charconv>
#include <cmath>
#include <string_view>

namespace ellc_lammps {

std::optional<double> to_number(const std::string& word) {
  double value = 0.0;
  const char* end = word.data() + word.size();
  const auto [ptr, code] = std::from_chars(word.data(), end, value);
  if (code != std::errc() || ptr != end) return std::nullopt;
  return value;
}

int read_contact_keyword(const std::vector<std::string>& arguments, std::size_t at, ellc::ContactModelBuilder& builder,
                         std::string& error) {
  const std::string& keyword = arguments[at];
  const std::string shared_name = keyword == "damping" ? "normal_damping" : keyword;  // older name
  const ellc::ContactParameterName* parameter = ellc::find_contact_parameter(shared_name);
  if (parameter == nullptr) return 0;
  if (at + 1 >= arguments.size()) {
    error = "keyword " + keyword + " needs 1 value(s)";
    return -1;
  }
  const std::string& word = arguments[at + 1];
  std::string expected;
  if (parameter->kind == ellc::ParameterKind::choice) {
    expected = builder.set(shared_name, word);
  } else {
    const auto value = to_number(word);
    if (!value) {
      error = keyword + ": '" + word + "' is not a number";
      return -1;
    }
    expected = builder.set(shared_name, *value);
  }
  if (!expected.empty()) {
    error = keyword + " = " + word + ": expected " + expected;
    return -1;
  }
  return 2;
}

std::string contact_keyword_names() {
  std::string known;
  for (const auto& parameter : ellc::kContactParameters) known += std::string(parameter.name) + ", ";
  return known + "damping";
}

namespace {

bool same_law(const ellc::LawParameters& x, const ellc::LawParameters& y) {
  const auto& f = x.fit;
  const auto& g = y.fit;
  return f.lambda_amplitude == g.lambda_amplitude && f.lambda_rate == g.lambda_rate &&
         f.lambda_offset == g.lambda_offset && f.epsilon_amplitude == g.epsilon_amplitude &&
         f.epsilon_rate == g.epsilon_rate && f.epsilon_offset == g.epsilon_offset &&
         f.transition_exponent == g.transition_exponent && x.yield_pressure_factor == y.yield_pressure_factor;
}

bool same_sub_models(const ellc::ContactModel& x, const ellc::ContactModel& y) {
  return x.normal == y.normal && x.damping == y.damping && x.tangential == y.tangential &&
         x.narrow_phase_final_step == y.narrow_phase_final_step;
}

}  // namespace

ParsedCoefficients parse_coefficients(const std::vector<std::string>& arguments) {
  ParsedCoefficients parsed;
  TypeCoefficients& c = parsed.coefficients;
  auto fail = [&parsed](std::string message) {
    parsed.error = std::move(message);
    return parsed;
  };
  if (arguments.size() < 3)
    return fail("expected pair_coeff I J E nu Y [keyword value ...], got " + std::to_string(arguments.size()) +
                " value(s) after the types");
  double* const positional[] = {&c.material.youngs_modulus, &c.material.poisson_ratio, &c.material.yield_stress};
  const char* const positional_names[] = {"E (Young's modulus)", "nu (Poisson ratio)", "Y (yield stress)"};
  for (std::size_t index = 0; index < 3; ++index) {
    const auto value = to_number(arguments[index]);
    if (!value) return fail(std::string(positional_names[index]) + ": '" + arguments[index] + "' is not a number");
    *positional[index] = *value;
  }

  // Keywords of the law's fit constants, which a scenario gives in its [model] table instead.
  struct LawKeyword {
    std::string_view name;
    std::vector<double*> targets;
  };
  auto& fit = c.model.law.fit;
  const LawKeyword law_keywords[] = {
      {"lambda", {&fit.lambda_amplitude, &fit.lambda_rate, &fit.lambda_offset}},
      {"epsilon", {&fit.epsilon_amplitude, &fit.epsilon_rate, &fit.epsilon_offset}},
      {"exponent", {&fit.transition_exponent}},
      {"yield_factor", {&c.model.law.yield_pressure_factor}},
  };
  ellc::ContactModelBuilder builder(c.model);
  for (std::size_t at = 3; at < arguments.size();) {
    const std::string& keyword = arguments[at];
    std::string error;
    const int used = read_contact_keyword(arguments, at, builder, error);
    if (used < 0) return fail(error);
    if (used > 0) {
      at += static_cast<std::size_t>(used);
      continue;
    }
    const LawKeyword* match = nullptr;
    for (const LawKeyword& entry : law_keywords)
      if (keyword == entry.name) match = &entry;
    if (match == nullptr) {
      return fail("unknown keyword '" + keyword + "' (expected " + contact_keyword_names() +
                  ", lambda, epsilon, exponent or yield_factor)");
    }
    if (at + match->targets.size() >= arguments.size())
      return fail("keyword " + keyword + " needs " + std::to_string(match->targets.size()) + " value(s)");
    for (std::size_t k = 0; k < match->targets.size(); ++k) {
      const auto value = to_number(arguments[at + 1 + k]);
      if (!value) return fail(keyword + ": '" + arguments[at + 1 + k] + "' is not a number");
      *match->targets[k] = *value;
    }
    at += 1 + match->targets.size();
  }
  const ellc::LawParameters law = c.model.law;
  c.model = builder.finish();
  c.model.law = law;

  if (std::string error = ellc::validation_error(c.material, "pair_coeff"); !error.empty()) return fail(error);
  if (std::string error = ellc::validation_error(c.model, "pair_coeff"); !error.empty()) return fail(error);
  return parsed;
}

ellc::InteractionContext explicit_pair(const TypeCoefficients& coefficients) {
  return ellc::make_interaction(coefficients.model, coefficients.material, coefficients.material);
}

ellc::InteractionContext mixed_pair(const TypeCoefficients& type_i, const TypeCoefficients& type_j,
                                    std::string& error) {
  error.clear();
  if (!same_law(type_i.model.law, type_j.model.law))
    error =
        "the two types have different law parameters (lambda, epsilon, exponent, yield_factor); give this "
        "pair of types its own pair_coeff line";
  else if (!same_sub_models(type_i.model, type_j.model))
    error =
        "the two types have different sub-models (normal, damping_model, tangential_model, "
        "narrow_phase_final_step); give this pair of types its own pair_coeff line";
  ellc::ContactModel model = type_i.model;
  model.friction = std::sqrt(type_i.model.friction * type_j.model.friction);
  model.normal_damping = std::sqrt(type_i.model.normal_damping * type_j.model.normal_damping);
  model.tangential_damping = std::sqrt(type_i.model.tangential_damping * type_j.model.tangential_damping);
  model.tangential_stiffness_ratio =
      std::sqrt(type_i.model.tangential_stiffness_ratio * type_j.model.tangential_stiffness_ratio);
  return ellc::make_interaction(model, type_i.material, type_j.material);
}

std::array<double, TypeCoefficients::kSerializedSize> TypeCoefficients::serialize() const {
  const auto& m = model;
  const auto& f = m.law.fit;
  return {material.youngs_modulus,
          material.poisson_ratio,
          material.yield_stress,
          m.friction,
          m.normal_damping,
          m.tangential_damping,
          m.tangential_stiffness_ratio,
          f.lambda_amplitude,
          f.lambda_rate,
          f.lambda_offset,
          f.epsilon_amplitude,
          f.epsilon_rate,
          f.epsilon_offset,
          f.transition_exponent,
          m.law.yield_pressure_factor,
          static_cast<double>(m.normal),
          static_cast<double>(m.damping),
          static_cast<double>(m.tangential),
          m.narrow_phase_final_step};
}

TypeCoefficients TypeCoefficients::deserialize(const std::array<double, kSerializedSize>& v) {
  TypeCoefficients c;
  c.material = {v[0], v[1], v[2]};
  auto& m = c.model;
  m.friction = v[3];
  m.normal_damping = v[4];
  m.tangential_damping = v[5];
  m.tangential_stiffness_ratio = v[6];
  m.law.fit = {v[7], v[8], v[9], v[10], v[11], v[12], v[13]};
  m.law.yield_pressure_factor = v[14];
  m.normal = static_cast<ellc::NormalModel>(static_cast<int>(v[15]));
  m.damping = static_cast<ellc::DampingModel>(static_cast<int>(v[16]));
  m.tangential = static_cast<ellc::TangentialModel>(static_cast<int>(v[17]));
  m.narrow_phase_final_step = v[18];
  return c;
}

}  // namespace ellc_lammps
