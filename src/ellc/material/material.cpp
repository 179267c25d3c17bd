#include "ellc/material/material.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace ellc {

namespace {
std::string describe(const std::string& field, double value, const char* expected) {
  char number[32];
  const auto end = std::to_chars(number, number + sizeof number, value).ptr;  // shortest round-trip form
  return field + " = " + std::string(number, end) + ": expected " + expected;
}
}  // namespace

std::string validation_error(const Material& material, const std::string& where) {
  if (!std::isfinite(material.youngs_modulus) || material.youngs_modulus <= 0.0)
    return describe(where + ".youngs_modulus", material.youngs_modulus, "a finite number > 0");
  if (!std::isfinite(material.poisson_ratio) || material.poisson_ratio <= -1.0 || material.poisson_ratio >= 0.5)
    return describe(where + ".poisson_ratio", material.poisson_ratio, "a number in the open interval (-1, 0.5)");
  if (!std::isfinite(material.yield_stress) || material.yield_stress <= 0.0)
    return describe(where + ".yield_stress", material.yield_stress, "a finite number > 0");
  return {};
}

double effective_modulus(const Material& body_i, const Material& body_j) noexcept {
  const double compliance_i = (1.0 - body_i.poisson_ratio * body_i.poisson_ratio) / body_i.youngs_modulus;
  const double compliance_j = (1.0 - body_j.poisson_ratio * body_j.poisson_ratio) / body_j.youngs_modulus;
  return 1.0 / (compliance_i + compliance_j);
}

ContactMaterial mix(const Material& body_i, const Material& body_j) noexcept {
  return {effective_modulus(body_i, body_j), std::min(body_i.yield_stress, body_j.yield_stress)};
}

}  // namespace ellc
