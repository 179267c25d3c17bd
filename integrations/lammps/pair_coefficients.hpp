#pragma once
// pair_coeff of pair ellipsoid/bk, without LAMMPS types (unit-testable):
//
//   pair_coeff I J  E nu Y  [friction mu] [damping eta_n] [tangential_damping eta_t]
//                           [tangential_stiffness kt_over_kn] [lambda m o p] [epsilon s t u]
//                           [exponent n] [yield_factor f]
//
// E, nu, Y describe the material of type I when I = J. For I ≠ J they describe the contact as if
// both bodies were of that material. Pairs of types without their own pair_coeff are mixed from
// the I I and J J lines: E_e from eq. (3), Y = min(Y_I, Y_J) (model-notes §5), friction and
// damping by the geometric mean, law parameters only if both types agree.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "contact_model.hpp"

namespace ellc_lammps {

struct TypeCoefficients {
  ellc::Material material;
  double friction = 0.0;
  double normal_damping = 0.0;
  double tangential_damping = 0.0;
  double tangential_stiffness = 1.0;
  ellc::LawParameters law;

  static constexpr std::size_t kSerializedSize = 15;
  [[nodiscard]] std::array<double, kSerializedSize> serialize() const;
  [[nodiscard]] static TypeCoefficients deserialize(const std::array<double, kSerializedSize>& values);
};

struct ParsedCoefficients {
  TypeCoefficients coefficients;
  std::string error;  // empty when valid
};

// `arguments` are the words after "pair_coeff I J".
[[nodiscard]] ParsedCoefficients parse_coefficients(const std::vector<std::string>& arguments);

// The contact of two bodies of the same material (an explicit pair_coeff line).
[[nodiscard]] PairCoefficients explicit_pair(const TypeCoefficients& coefficients);

// Mixing for types I ≠ J without their own line. Sets `error` when the law parameters differ.
[[nodiscard]] PairCoefficients mixed_pair(const TypeCoefficients& type_i, const TypeCoefficients& type_j,
                                          std::string& error);

}  // namespace ellc_lammps
