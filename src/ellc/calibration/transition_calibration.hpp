#pragma once
// Calibration of the elastic–plastic transition (paper Sec. 4, eq. 51, 28, 52) from force data.
//
//  1. Per case, λ_FEM at each loading point beyond δ_Y from eq. (51):
//       λ_FEM = (F − F_pY) / (π Y (c_c² − c_Y²)),   c_c² = R_e δ f1²/f2 (eq. 9).
//     Eq. (28) is fitted to it for (λ_max, ε_max, n). Each residual is weighted by
//     π Y (c_c² − c_Y²) / F, so that w (λ_model − λ_FEM) = (F_model − F) / F: the λ fit the paper
//     did, with points counted by their relative force error (λ_FEM is ill-conditioned near δ_Y).
//     A case whose data stops before the plateau (c_c < ε_max c_Y) cannot pin n: its λ_max, ε_max
//     are fitted with n held at the prior's (the paper fixed n = 1.8).
//  2. One n shared by all cases (the paper's single n): a joint fit of n with the λ_max, ε_max of
//     every case that pins n; the prior's n when none does.
//  3. Across cases, eq. (52): λ_max = m exp(o x) + p, ε_max = s exp(t x) + u, x = R_e/r̂^{I,J}.
//     Four or more distinct x fit all three constants; two or three fit m, p (s, u) with o (t)
//     kept from the prior; one fits p (u) only.
//     Form stiffness_ratio (several materials, issue 14): eq. (52) times (η/η_ref)^q with
//     η = E_e/Y, fitted in one problem over all cases; q_λ, q_ε need a material with η ≠ η_ref
//     (η_ref from the prior, NMC's by default). With the paper's form all cases must share one
//     material. A cross-case fit that does not converge throws, naming the residual.
// All least-squares problems are solved by Ceres (Levenberg–Marquardt, automatic derivatives).

#include <span>
#include <string>
#include <vector>

#include "ellc/calibration/calibration_case.hpp"
#include "ellc/hertz/elliptic_hertz.hpp"
#include "ellc/law/contact_constants.hpp"
#include "ellc/law/transition_fit.hpp"

namespace ellc {

struct CalibrationOptions {
  HertzMode hertz = HertzMode::hale;
  // Supplies yield_pressure_factor and the constants kept when there are too few cases.
  LawParameters prior;
  // A case whose force stays within this relative distance of the Hertz curve at every point
  // beyond δ_Y is elastic: it cannot tell anything about the transition.
  double elastic_tolerance = 0.02;
  std::size_t min_plastic_points = 4;  // loading points beyond δ_Y needed per case
  // paper: one material, eq. (52). stiffness_ratio: several materials, eq. (52) × (E_e/Y ÷ η_ref)^q.
  TransitionForm form = TransitionForm::paper;
  int max_iterations = 300;  // Ceres iterations per cross-case fit; running out is an error (no convergence)
};

// One point of the λ profile (Fig. 11).
struct LambdaSample {
  double overlap = 0.0;               // δ
  double force = 0.0;                 // F (data)
  double contact_radius_ratio = 0.0;  // c_c / c_Y
  double lambda = 0.0;                // λ_FEM, eq. (51)
  double weight = 0.0;                // π Y (c_c² − c_Y²) / F
};

struct TransitionPoint {
  double lambda_max = 0.0;
  double epsilon_max = 0.0;
  double exponent = 0.0;  // n
};

struct CaseCalibration {
  std::string name;
  double radius_ratio = 0.0;       // R_e / r̂^{I,J}
  double equivalent_radius = 0.0;  // R_e
  double yield_overlap = 0.0;      // δ_Y
  double yield_force = 0.0;        // F_pY
  double stiffness_ratio = 0.0;    // η = E_e/Y of the case's material pair
  std::vector<LambdaSample> profile;
  TransitionPoint own;               // step 1: λ_max, ε_max, n of this case alone
  bool own_exponent_fitted = false;  // false: the data does not pin n (no plateau), own.n is the prior's
  TransitionPoint shared;            // step 2: with the n shared by all cases
  double own_rms = 0.0;              // RMS relative force error of step 1 over the profile points
  double shared_rms = 0.0;           // same for step 2
  double model_rms = 0.0;            // same for the final eq. (52) constants (the law as `ellc curve` runs it)
  bool plateau_reached = false;      // the data reaches c_c ≥ ε_max c_Y (else λ_max, ε_max are extrapolated)
  bool transition_found = true;      // false: ε_max of step 1 ended on its lower bound, λ_FEM never rises
};

struct CalibrationResult {
  std::vector<CaseCalibration> cases;
  LawParameters law;  // the calibrated m, o, p, s, t, u, n and yield_pressure_factor
  HertzMode hertz = HertzMode::hale;
  bool rates_fitted = false;       // o, t fitted (≥ 4 distinct R_e/r̂)
  bool amplitudes_fitted = false;  // m, s fitted (≥ 2 distinct R_e/r̂)
  bool exponent_fitted = false;    // n fitted (some case reaches the plateau), else the prior's
  bool stiffness_fitted = false;   // q_λ, q_ε fitted (form stiffness_ratio)
  bool anchored = false;           // stiffness_ratio with one material: eq. (52) and n are the prior's
  double lambda_rms = 0.0;         // RMS of λ_max(x, η) − per-case λ_max over the cases
  double epsilon_rms = 0.0;        // same for ε_max
  std::vector<std::string> warnings;
};

// Step 1 input: eq. (51) on the virgin-loading points (δ at or above every earlier δ) with
// δ ≥ 1.02 δ_Y (closer to the yield point eq. 51 divides by almost zero and says nothing about λ).
[[nodiscard]] std::vector<LambdaSample> lambda_profile(const ContactConstants& constants,
                                                       std::span<const double> overlaps,
                                                       std::span<const double> forces);

// Eq. (28) as a function of c_c/c_Y (λ_max beyond ε_max).
[[nodiscard]] double profile_lambda(const TransitionPoint& point, double contact_radius_ratio,
                                    double yield_pressure_factor) noexcept;

// Eq. (52) fit of y = amplitude exp(rate x) + offset. `fixed_rate`/`fixed_amplitude` are used when
// there are too few distinct x (see above). Returns {amplitude, rate, offset}.
struct ExponentialFit {
  double amplitude = 0.0;
  double rate = 0.0;
  double offset = 0.0;
  bool rate_fitted = false;
  bool amplitude_fitted = false;
  double stiffness_exponent = 0.0;  // q of the stiffness_ratio form (0 for the paper's)
  bool stiffness_fitted = false;
  bool converged = true;      // false: no start of the Ceres problem converged
  double rms = 0.0;           // RMS residual of y
  std::string solver_report;  // Ceres' message when not converged
};
[[nodiscard]] ExponentialFit fit_exponential(std::span<const double> x, std::span<const double> y,
                                             double fixed_amplitude, double fixed_rate, int max_iterations = 300);

// The stiffness_ratio form: y = (amplitude exp(rate x) + offset) (η/η_ref)^q over cases of several
// materials. x, η, y per case; which of amplitude, rate are fitted follows the distinct x as for
// eq. (52); q is fitted when some η differs from η_ref, and with a single η (≠ η_ref) the
// prior's amplitude, rate, offset are kept and only q is fitted.
[[nodiscard]] ExponentialFit fit_stiffness_form(std::span<const double> x, std::span<const double> stiffness_ratio,
                                                std::span<const double> y, double reference_stiffness_ratio,
                                                const ExponentialFit& prior, int max_iterations = 300);

// The whole calibration. Throws InputError (naming the case) for unusable data, e.g. data that
// never leaves the elastic regime.
[[nodiscard]] CalibrationResult calibrate(const std::vector<CalibrationCase>& cases,
                                          const CalibrationOptions& options = {});

// The `[model]` table for `ellc curve` / `ellc dem`, with the per-case results as comments.
[[nodiscard]] std::string model_table_toml(const CalibrationResult& result);

}  // namespace ellc
