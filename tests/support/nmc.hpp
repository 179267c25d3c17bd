#pragma once
// NMC, the cathode material of the paper's examples (Sec. 5): E = 142000 MPa, ν = 0.25,
// Y = 7900 MPa. The one place the C++ tests spell these numbers; a test that feeds them to a
// parser gets them as text from here too.

#include <sstream>
#include <string>
#include <vector>

#include "ellc/material/material.hpp"

namespace ellc::test {

inline constexpr Material kNmc{142000.0, 0.25, 7900.0};

// A value as text that reads back exactly (142000, 0.25, 7900).
[[nodiscard]] inline std::string exact_text(double value) {
  std::ostringstream out;
  out.precision(17);
  out << value;
  return out.str();
}

// The same as a TOML float: ".0" appended to what would read as an integer.
[[nodiscard]] inline std::string toml_float(double value) {
  std::string text = exact_text(value);
  if (text.find_first_of(".en") == std::string::npos) text += ".0";
  return text;
}

// The [material] table of a case or scenario file:
// "[material]\nyoungs_modulus = 142000.0\npoisson_ratio = 0.25\nyield_stress = 7900.0\n".
[[nodiscard]] inline std::string nmc_material_toml() {
  return "[material]\nyoungs_modulus = " + toml_float(kNmc.youngs_modulus) +
         "\npoisson_ratio = " + toml_float(kNmc.poisson_ratio) + "\nyield_stress = " + toml_float(kNmc.yield_stress) +
         "\n";
}

// The positional E ν Y of a pair_coeff line of pair_style ellipsoid/bk ("142000", "0.25", "7900"),
// followed by `keywords`.
[[nodiscard]] inline std::vector<std::string> nmc_pair_coeff(std::vector<std::string> keywords = {}) {
  std::vector<std::string> words{exact_text(kNmc.youngs_modulus), exact_text(kNmc.poisson_ratio),
                                 exact_text(kNmc.yield_stress)};
  words.insert(words.end(), keywords.begin(), keywords.end());
  return words;
}

}  // namespace ellc::test
