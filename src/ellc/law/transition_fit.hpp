#pragma once
// The elastic–plastic transition fits (paper eq. 52–54): λ_max and ε_max as functions of the
// dimensionless effective radius R_e / r̂^{I,J}, plus the λ-profile exponent n of eq. (28).
// Calibrated for NMC with aspect ratios 1:[0.5..2]:[0.5..2]; all constants are parameters.

#include <string>

namespace ellc {

struct TransitionFit {
  // λ_max = m exp(o R_e/r̂) + p, eq. (52); defaults eq. (53).
  double lambda_amplitude = 1.05;  // m
  double lambda_rate = -4.62;      // o
  double lambda_offset = 2.42;     // p
  // ε_max = s exp(t R_e/r̂) + u, eq. (52); defaults eq. (53).
  double epsilon_amplitude = 8.19;   // s
  double epsilon_rate = -6.14;       // t
  double epsilon_offset = 1.14;      // u
  double transition_exponent = 1.8;  // n of eq. (28)

  [[nodiscard]] double lambda_max(double radius_ratio) const noexcept;   // eq. (52)
  [[nodiscard]] double epsilon_max(double radius_ratio) const noexcept;  // eq. (52)
};

struct LawParameters {
  TransitionFit fit;
  double yield_pressure_factor = 1.6;  // p_Y = 1.6 Y at first yield (Sec. 3)

  // Thornton's elastic–fully-plastic variant: λ ≡ 1.6 (no transition hardening), the "thin line"
  // of the paper's Fig. 6. docs/model.md §4: the law reduces to Thornton (1997) for spheres.
  [[nodiscard]] LawParameters elastic_fully_plastic() const noexcept;
};

// Empty when usable; otherwise names the parameter, its value and what was expected.
[[nodiscard]] std::string validation_error(const LawParameters& parameters);

}  // namespace ellc
