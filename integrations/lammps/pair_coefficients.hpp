#pragma once
// pair_coeff of pair ellipsoid/bk, without LAMMPS types (unit-testable):
//
//   pair_coeff I J  E nu Y  [contact-model keywords] [lambda m o p] [epsilon s t u]
//                           [exponent n] [yield_factor f]
//
// The contact-model keywords are the shared vocabulary of src/ellc/contact/contact_parameters.hpp
// (normal, damping_model, damping_ratio, normal_damping, tangential_damping, tangential_model,
// tangential_stiffness, friction, narrow_phase_final_step), the same names as the [contact] table
// of an `ellc dem` scenario; `damping` is the older name of normal_damping and still accepted.
//
// E, nu, Y describe the material of type I when I = J. For I ≠ J they describe the contact as if
// both bodies were of that material. Pairs of types without their own pair_coeff are mixed from
// the I I and J J lines: E_e from eq. (3), Y = min(Y_I, Y_J) (docs/model.md §5), friction and
// damping by the geometric mean, sub-models and law parameters only if both types agree.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "ellc/contact/contact_model.hpp"
#include "ellc/contact/contact_parameters.hpp"
#include "ellc/material/material.hpp"

namespace ellc_lammps {

struct TypeCoefficients {
  ellc::Material material;
  ellc::ContactModel model;  // LAMMPS defaults: no damping, no friction, the normal solved to rounding;
                             // `hertz` is the pair style's setting, applied in init_one

  static constexpr std::size_t kSerializedSize = 19;
  [[nodiscard]] std::array<double, kSerializedSize> serialize() const;
  [[nodiscard]] static TypeCoefficients deserialize(const std::array<double, kSerializedSize>& values);
};

struct ParsedCoefficients {
  TypeCoefficients coefficients;
  std::string error;  // empty when valid
};

// `arguments` are the words after "pair_coeff I J".
[[nodiscard]] ParsedCoefficients parse_coefficients(const std::vector<std::string>& arguments);

// One contact-model keyword of the shared vocabulary (or `damping`, the older name of
// normal_damping) at arguments[at] and its value, handed to `builder`. Returns the words used:
// 0 when arguments[at] is not such a keyword, 2 when accepted; -1 with `error` set when the value
// is missing or refused. pair_coeff and fix wall/ellipsoid/bk read their keywords through this.
[[nodiscard]] int read_contact_keyword(const std::vector<std::string>& arguments, std::size_t at,
                                       ellc::ContactModelBuilder& builder, std::string& error);

// "normal, damping_model, ..., narrow_phase_final_step, damping": the keywords read_contact_keyword knows.
[[nodiscard]] std::string contact_keyword_names();

// A number as LAMMPS input writes it (the whole word; "inf" included), else nothing.
[[nodiscard]] std::optional<double> to_number(const std::string& word);

// The contact of two bodies of the same material (an explicit pair_coeff line).
[[nodiscard]] ellc::InteractionContext explicit_pair(const TypeCoefficients& coefficients);

// Mixing for types I ≠ J without their own line. Sets `error` when the sub-models or the law
// parameters differ.
[[nodiscard]] ellc::InteractionContext mixed_pair(const TypeCoefficients& type_i, const TypeCoefficients& type_j,
                                                  std::string& error);

}  // namespace ellc_lammps
