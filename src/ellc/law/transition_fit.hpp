#pragma once
// The elastic–plastic transition fits (paper eq. 52–54): λ_max and ε_max as functions of the
// dimensionless effective radius R_e / r̂^{I,J}, plus the λ-profile exponent n of eq. (28).
// Calibrated for NMC with aspect ratios 1:[0.5..2]:[0.5..2]; all constants are parameters.
//
// The form `stiffness_ratio` (issue 14, docs/calibration.md "Several materials") scales both
// by a power of the stiffness-to-hardness ratio η = E_e/Y relative to a reference material:
//   λ_max = (m exp(o R_e/r̂) + p) (η/η_ref)^{q_λ},   ε_max = (s exp(t R_e/r̂) + u) (η/η_ref)^{q_ε}.
// At η = η_ref (NMC's by default) it is eq. (52) exactly; the paper's form ignores η.

#include <string>

namespace ellc {

// E_e/Y of the paper's NMC (E = 142 GPa, ν = 0.25, Y = 7.9 GPa, two equal bodies: E_e = E/(2(1 − ν²))).
inline constexpr double kNmcStiffnessRatio = 142000.0 / (2.0 * (1.0 - 0.25 * 0.25)) / 7900.0;

enum class TransitionForm {
  paper,            // eq. (52): λ_max, ε_max depend on R_e/r̂ only
  stiffness_ratio,  // eq. (52) times (η/η_ref)^q, η = E_e/Y
};

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
  // Form stiffness_ratio only (zero exponents make it eq. 52 for every η).
  TransitionForm form = TransitionForm::paper;
  double lambda_stiffness_exponent = 0.0;                 // q_λ
  double epsilon_stiffness_exponent = 0.0;                // q_ε
  double reference_stiffness_ratio = kNmcStiffnessRatio;  // η_ref

  // Eq. (52) at the reference material (the paper's form for any material).
  [[nodiscard]] double lambda_max(double radius_ratio) const noexcept;
  [[nodiscard]] double epsilon_max(double radius_ratio) const noexcept;
  // The selected form at a contact with stiffness ratio η = E_e/Y (eq. 3 for E_e).
  [[nodiscard]] double lambda_max_for(double radius_ratio, double stiffness_ratio) const noexcept;
  [[nodiscard]] double epsilon_max_for(double radius_ratio, double stiffness_ratio) const noexcept;
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
