#include "pair_coefficients.hpp"

#include <charconv>
#include <cmath>
#include <string_view>

namespace ellc_lammps {

namespace {

std::optional<double> to_number(const std::string& word) {
  double value = 0.0;
  const char* end = word.data() + word.size();
  const auto [ptr, code] = std::from_chars(word.data(), end, value);
  if (code != std::errc() || ptr != end) return std::nullopt;
  return value;
}

std::string check_non_negative(const char* name, double value) {
  if (std::isfinite(value) && value >= 0.0) return {};
  return std::string(name) + " = " + std::to_string(value) + ": expected a finite number >= 0";
}

bool same_law(const ellc::LawParameters& x, const ellc::LawParameters& y) {
  const auto& f = x.fit;
  const auto& g = y.fit;
  return f.lambda_amplitude == g.lambda_amplitude && f.lambda_rate == g.lambda_rate &&
         f.lambda_offset == g.lambda_offset && f.epsilon_amplitude == g.epsilon_amplitude &&
         f.epsilon_rate == g.epsilon_rate && f.epsilon_offset == g.epsilon_offset &&
         f.transition_exponent == g.transition_exponent && x.yield_pressure_factor == y.yield_pressure_factor;
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

  struct Keyword {
    std::string_view name;
    std::vector<double*> targets;
  };
  auto& fit = c.law.fit;
  const Keyword keywords[] = {
      {"friction", {&c.friction}},
      {"damping", {&c.normal_damping}},
      {"tangential_damping", {&c.tangential_damping}},
      {"tangential_stiffness", {&c.tangential_stiffness}},
      {"lambda", {&fit.lambda_amplitude, &fit.lambda_rate, &fit.lambda_offset}},
      {"epsilon", {&fit.epsilon_amplitude, &fit.epsilon_rate, &fit.epsilon_offset}},
      {"exponent", {&fit.transition_exponent}},
      {"yield_factor", {&c.law.yield_pressure_factor}},
  };
  for (std::size_t at = 3; at < arguments.size();) {
    const Keyword* match = nullptr;
    for (const Keyword& keyword : keywords)
      if (arguments[at] == keyword.name) match = &keyword;
    if (match == nullptr)
      return fail("unknown keyword '" + arguments[at] +
                  "' (expected friction, damping, tangential_damping, tangential_stiffness, lambda, epsilon, "
                  "exponent or yield_factor)");
    if (at + match->targets.size() >= arguments.size())
      return fail("keyword " + arguments[at] + " needs " + std::to_string(match->targets.size()) + " value(s)");
    for (std::size_t k = 0; k < match->targets.size(); ++k) {
      const auto value = to_number(arguments[at + 1 + k]);
      if (!value) return fail(arguments[at] + ": '" + arguments[at + 1 + k] + "' is not a number");
      *match->targets[k] = *value;
    }
    at += 1 + match->targets.size();
  }

  if (std::string error = ellc::validation_error(c.material, "pair_coeff"); !error.empty()) return fail(error);
  if (std::string error = ellc::validation_error(c.law); !error.empty()) return fail(error);
  for (const auto& [name, value] : {std::pair{"friction", c.friction}, std::pair{"damping", c.normal_damping},
                                    std::pair{"tangential_damping", c.tangential_damping},
                                    std::pair{"tangential_stiffness", c.tangential_stiffness}})
    if (std::string error = check_non_negative(name, value); !error.empty()) return fail(error);
  return parsed;
}

namespace {
PairCoefficients with_model(const TypeCoefficients& c, const ellc::ContactMaterial& material) {
  PairCoefficients pair;
  pair.material = material;
  pair.friction = c.friction;
  pair.normal_damping = c.normal_damping;
  pair.tangential_damping = c.tangential_damping;
  pair.tangential_stiffness = c.tangential_stiffness;
  pair.law = c.law;
  return pair;
}
}  // namespace

PairCoefficients explicit_pair(const TypeCoefficients& coefficients) {
  return with_model(coefficients, ellc::mix(coefficients.material, coefficients.material));
}

PairCoefficients mixed_pair(const TypeCoefficients& type_i, const TypeCoefficients& type_j, std::string& error) {
  error.clear();
  if (!same_law(type_i.law, type_j.law))
    error = "the two types have different law parameters (lambda, epsilon, exponent, yield_factor); give this "
            "pair of types its own pair_coeff line";
  PairCoefficients pair = with_model(type_i, ellc::mix(type_i.material, type_j.material));
  pair.friction = std::sqrt(type_i.friction * type_j.friction);
  pair.normal_damping = std::sqrt(type_i.normal_damping * type_j.normal_damping);
  pair.tangential_damping = std::sqrt(type_i.tangential_damping * type_j.tangential_damping);
  pair.tangential_stiffness = std::sqrt(type_i.tangential_stiffness * type_j.tangential_stiffness);
  return pair;
}

std::array<double, TypeCoefficients::kSerializedSize> TypeCoefficients::serialize() const {
  return {material.youngs_modulus, material.poisson_ratio,  material.yield_stress,   friction,
          normal_damping,          tangential_damping,      tangential_stiffness,    law.fit.lambda_amplitude,
          law.fit.lambda_rate,     law.fit.lambda_offset,   law.fit.epsilon_amplitude, law.fit.epsilon_rate,
          law.fit.epsilon_offset,  law.fit.transition_exponent, law.yield_pressure_factor};
}

TypeCoefficients TypeCoefficients::deserialize(const std::array<double, kSerializedSize>& v) {
  TypeCoefficients c;
  c.material = {v[0], v[1], v[2]};
  c.friction = v[3];
  c.normal_damping = v[4];
  c.tangential_damping = v[5];
  c.tangential_stiffness = v[6];
  c.law.fit = {v[7], v[8], v[9], v[10], v[11], v[12], v[13]};
  c.law.yield_pressure_factor = v[14];
  return c;
}

}  // namespace ellc_lammps
