#include "ellc/calibration/transition_calibration.hpp"

#include <ceres/ceres.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <optional>
#include <sstream>

#include "ellc/geometry/tip_contact.hpp"
#include "ellc/io/input_error.hpp"
#include "ellc/law/contact_law.hpp"

namespace ellc {

namespace {

constexpr double kPi = std::numbers::pi;

// Bounds keep the problems well posed; a fit that ends on one of them is reported as unusable.
constexpr double kLambdaMaxUpper = 50.0;
constexpr double kEpsilonMaxLower = 1.0 + 1e-3;
constexpr double kEpsilonMaxUpper = 100.0;
constexpr double kExponentLower = 0.05;
constexpr double kExponentUpper = 20.0;
constexpr double kRateBound = 25.0;
// Profile points need c_c² ≥ 1.02 c_Y² (δ ≥ 1.02 δ_Y).
constexpr double kYieldMargin = 1.02;
// Eq. (52) has three constants; with three points it would interpolate them exactly, which
// extrapolates wildly. The rate is fitted from four distinct R_e/r̂ on.
constexpr std::size_t kDistinctForRate = 4;

// Eq. (28) in c_c/c_Y, templated for Ceres' automatic derivatives.
template <typename T>
T lambda_of(const T& lambda_max, const T& epsilon_max, const T& exponent, double contact_radius_ratio,
            double yield_pressure_factor) {
  using std::pow;
  const T progress_left = (epsilon_max - contact_radius_ratio) / (epsilon_max - 1.0);
  if (!(progress_left > T(0.0))) return lambda_max;  // plateau: fully plastic
  return lambda_max - (lambda_max - yield_pressure_factor) * pow(progress_left, exponent);
}

// Weighted λ residuals of one case: w (λ_model − λ_FEM) = relative force error.
struct ProfileResiduals {
  const std::vector<LambdaSample>* samples;
  double yield_pressure_factor;

  template <typename T>
  bool operator()(const T* const shape, const T* const exponent, T* residuals) const {
    for (std::size_t index = 0; index < samples->size(); ++index) {
      const LambdaSample& sample = (*samples)[index];
      residuals[index] =
          sample.weight *
          (lambda_of(shape[0], shape[1], exponent[0], sample.contact_radius_ratio, yield_pressure_factor) -
           sample.lambda);
    }
    return true;
  }
};

struct ExponentialResiduals {
  std::span<const double> x;
  std::span<const double> y;

  template <typename T>
  bool operator()(const T* const parameters, T* residuals) const {
    using std::exp;
    for (std::size_t index = 0; index < x.size(); ++index)
      residuals[index] = parameters[0] * exp(parameters[1] * x[index]) + parameters[2] - y[index];
    return true;
  }
};

ceres::Solver::Options solver_options() {
  ceres::Solver::Options options;
  options.minimizer_type = ceres::TRUST_REGION;
  options.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = 300;
  options.function_tolerance = 1e-14;
  options.gradient_tolerance = 1e-14;
  options.parameter_tolerance = 1e-12;
  options.logging_type = ceres::SILENT;
  options.minimizer_progress_to_stdout = false;
  options.num_threads = 1;
  return options;
}

void add_case(ceres::Problem& problem, const std::vector<LambdaSample>& samples, double yield_pressure_factor,
              double* shape, double* exponent) {
  auto* cost = new ceres::AutoDiffCostFunction<ProfileResiduals, ceres::DYNAMIC, 2, 1>(
      new ProfileResiduals{&samples, yield_pressure_factor}, static_cast<int>(samples.size()));
  problem.AddResidualBlock(cost, nullptr, shape, exponent);
  problem.SetParameterLowerBound(shape, 0, yield_pressure_factor);
  problem.SetParameterUpperBound(shape, 0, kLambdaMaxUpper);
  problem.SetParameterLowerBound(shape, 1, kEpsilonMaxLower);
  problem.SetParameterUpperBound(shape, 1, kEpsilonMaxUpper);
  problem.SetParameterLowerBound(exponent, 0, kExponentLower);  // shared blocks: set again, harmless
  problem.SetParameterUpperBound(exponent, 0, kExponentUpper);
}

double rms_error(const std::vector<LambdaSample>& samples, const TransitionPoint& point, double yield_pressure_factor) {
  double sum = 0.0;
  for (const LambdaSample& sample : samples) {
    const double residual =
        sample.weight * (profile_lambda(point, sample.contact_radius_ratio, yield_pressure_factor) - sample.lambda);
    sum += residual * residual;
  }
  return samples.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(samples.size()));
}

// Step 1: (λ_max, ε_max, n) of one case, from a few starting points (the kink at ε_max makes the
// problem non-convex); the lowest cost wins. With `fixed_exponent`, n is held there.
TransitionPoint fit_case(const std::vector<LambdaSample>& samples, double yield_pressure_factor,
                         std::optional<double> fixed_exponent = std::nullopt) {
  double largest_ratio = 0.0;
  double last_lambda = yield_pressure_factor;
  for (const LambdaSample& sample : samples) {
    if (sample.contact_radius_ratio >= largest_ratio) last_lambda = sample.lambda;
    largest_ratio = std::max(largest_ratio, sample.contact_radius_ratio);
  }
  const double lambda_start = std::clamp(last_lambda, yield_pressure_factor + 0.05, kLambdaMaxUpper * 0.5);
  const std::vector<double> exponent_starts =
      fixed_exponent ? std::vector<double>{*fixed_exponent} : std::vector<double>{1.0, 2.0, 3.5};
  TransitionPoint best;
  double best_cost = std::numeric_limits<double>::infinity();
  const ceres::Solver::Options options = solver_options();
  for (const double epsilon_start : {1.5, 2.5, 4.0, 7.0, 12.0}) {
    for (const double exponent_start : exponent_starts) {
      double shape[2] = {lambda_start, epsilon_start};
      double exponent = exponent_start;
      ceres::Problem problem;
      add_case(problem, samples, yield_pressure_factor, shape, &exponent);
      if (fixed_exponent) problem.SetParameterBlockConstant(&exponent);
      ceres::Solver::Summary summary;
      ceres::Solve(options, &problem, &summary);
      if (summary.final_cost < best_cost && std::isfinite(summary.final_cost)) {
        best_cost = summary.final_cost;
        best = {shape[0], shape[1], exponent};
      }
    }
  }
  return best;
}

bool at_bound(double value, double lower, double upper) {
  return value <= lower * (1 + 1e-6) || value >= upper * (1 - 1e-6);
}

// Whether the data of a case pins its own n: the λ profile reaches its plateau (c_c ≥ ε_max c_Y)
// and n is not on a bound. Without a plateau, λ_max, ε_max and n trade off against each other
// (a large n with a large ε_max mimics a saturating curve), so n must come from elsewhere.
bool exponent_identified(const CaseCalibration& entry) {
  return !entry.profile.empty() && entry.profile.back().contact_radius_ratio >= entry.own.epsilon_max &&
         !at_bound(entry.own.exponent, kExponentLower, kExponentUpper);
}

// Step 2: one n for all cases (the paper's single n). Fitted jointly with every case's λ_max, ε_max
// over the cases whose data pins n; `fallback` (the prior's n) when none does. The other cases then
// get λ_max, ε_max with that n held fixed. Returns whether n was fitted.
bool fit_shared_exponent(std::vector<CaseCalibration>& cases, double yield_pressure_factor, double fallback,
                         double& exponent) {
  std::vector<std::size_t> informative;
  std::vector<double> exponents;
  for (std::size_t index = 0; index < cases.size(); ++index) {
    if (!cases[index].own_exponent_fitted) continue;
    informative.push_back(index);
    exponents.push_back(cases[index].own.exponent);
  }
  exponent = fallback;
  if (!informative.empty()) {
    std::nth_element(exponents.begin(), exponents.begin() + static_cast<std::ptrdiff_t>(exponents.size() / 2),
                     exponents.end());
    exponent = exponents[exponents.size() / 2];
    std::vector<std::array<double, 2>> shapes;
    shapes.reserve(informative.size());
    for (const std::size_t index : informative) shapes.push_back({cases[index].own.lambda_max, cases[index].own.epsilon_max});
    ceres::Problem problem;
    for (std::size_t slot = 0; slot < informative.size(); ++slot)
      add_case(problem, cases[informative[slot]].profile, yield_pressure_factor, shapes[slot].data(), &exponent);
    ceres::Solver::Summary summary;
    ceres::Solve(solver_options(), &problem, &summary);
    for (std::size_t slot = 0; slot < informative.size(); ++slot)
      cases[informative[slot]].shared = {shapes[slot][0], shapes[slot][1], exponent};
  }
  for (auto& entry : cases)
    if (!entry.own_exponent_fitted || informative.empty()) entry.shared = fit_case(entry.profile, yield_pressure_factor, exponent);
  return !informative.empty();
}

std::size_t distinct_count(std::span<const double> values) {
  std::vector<double> sorted(values.begin(), values.end());
  std::sort(sorted.begin(), sorted.end());
  std::size_t count = 0;
  for (std::size_t index = 0; index < sorted.size(); ++index)
    if (index == 0 || sorted[index] - sorted[index - 1] > 1e-6 * std::max(1.0, std::abs(sorted[index]))) ++count;
  return count;
}

// Least squares for y ≈ a g(x) + b with g(x) = exp(rate x) fixed: a 2×2 linear problem.
std::pair<double, double> linear_amplitude_offset(std::span<const double> x, std::span<const double> y, double rate) {
  Eigen::MatrixXd basis(static_cast<Eigen::Index>(x.size()), 2);
  Eigen::VectorXd target(static_cast<Eigen::Index>(x.size()));
  for (std::size_t index = 0; index < x.size(); ++index) {
    const auto row = static_cast<Eigen::Index>(index);
    basis(row, 0) = std::exp(rate * x[index]);
    basis(row, 1) = 1.0;
    target(row) = y[index];
  }
  const Eigen::Vector2d solution = basis.colPivHouseholderQr().solve(target);
  return {solution(0), solution(1)};
}

std::string format_percent(double fraction) {
  std::ostringstream out;
  out.precision(3);
  out << 100.0 * fraction << " %";
  return out.str();
}

}  // namespace

double profile_lambda(const TransitionPoint& point, double contact_radius_ratio, double yield_pressure_factor) noexcept {
  return lambda_of(point.lambda_max, point.epsilon_max, point.exponent, contact_radius_ratio, yield_pressure_factor);
}

std::vector<LambdaSample> lambda_profile(const ContactConstants& c, std::span<const double> overlaps,
                                         std::span<const double> forces) {
  std::vector<LambdaSample> samples;
  const std::size_t count = std::min(overlaps.size(), forces.size());
  const double yield_radius_sq = c.yield_contact_radius * c.yield_contact_radius;
  double largest_overlap = 0.0;
  for (std::size_t index = 0; index < count; ++index) {
    const double overlap = overlaps[index];
    if (overlap < largest_overlap) continue;  // unloading or reloading below δ_*: not the envelope
    largest_overlap = overlap;
    const double contact_radius_sq = c.contact_radius_sq_per_overlap * overlap;  // eq. (9)
    // Eq. (51) divides by c_c² − c_Y²: points this close to the yield point say nothing about λ.
    if (contact_radius_sq <= kYieldMargin * yield_radius_sq || !(forces[index] > 0.0)) continue;
    const double plastic_scale = kPi * c.yield_stress * (contact_radius_sq - yield_radius_sq);
    samples.push_back({overlap, forces[index], std::sqrt(contact_radius_sq) / c.yield_contact_radius,
                       (forces[index] - c.yield_force) / plastic_scale,  // eq. (51)
                       plastic_scale / forces[index]});
  }
  return samples;
}

ExponentialFit fit_exponential(std::span<const double> x, std::span<const double> y, double fixed_amplitude,
                               double fixed_rate) {
  ExponentialFit fit;
  const std::size_t distinct = distinct_count(x);
  if (distinct == 0) return fit;
  if (distinct == 1) {
    fit.amplitude = fixed_amplitude;
    fit.rate = fixed_rate;
    double sum = 0.0;
    for (std::size_t index = 0; index < x.size(); ++index) sum += y[index] - fixed_amplitude * std::exp(fixed_rate * x[index]);
    fit.offset = sum / static_cast<double>(x.size());
    return fit;
  }
  if (distinct < kDistinctForRate) {
    fit.rate = fixed_rate;
    std::tie(fit.amplitude, fit.offset) = linear_amplitude_offset(x, y, fixed_rate);
    fit.amplitude_fitted = true;
    return fit;
  }
  fit.amplitude_fitted = fit.rate_fitted = true;
  double best_cost = std::numeric_limits<double>::infinity();
  const ceres::Solver::Options options = solver_options();
  for (const double rate_start : {fixed_rate, -20.0, -12.0, -8.0, -5.0, -3.0, -1.5, -0.5, 0.5, 2.0}) {
    double parameters[3];
    std::tie(parameters[0], parameters[2]) = linear_amplitude_offset(x, y, rate_start);
    parameters[1] = rate_start;
    ceres::Problem problem;
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<ExponentialResiduals, ceres::DYNAMIC, 3>(
                                 new ExponentialResiduals{x, y}, static_cast<int>(x.size())),
                             nullptr, parameters);
    problem.SetParameterLowerBound(parameters, 1, -kRateBound);
    problem.SetParameterUpperBound(parameters, 1, kRateBound);
    ceres::Solver::Summary summary;
    ceres::Solve(options, &problem, &summary);
    if (std::isfinite(summary.final_cost) && summary.final_cost < best_cost * (1.0 - 1e-9)) {
      best_cost = summary.final_cost;
      fit.amplitude = parameters[0];
      fit.rate = parameters[1];
      fit.offset = parameters[2];
    }
  }
  return fit;
}

CalibrationResult calibrate(const std::vector<CalibrationCase>& cases, const CalibrationOptions& options) {
  if (cases.empty()) throw InputError("", "no calibration cases: expected at least one CSV of overlap and force");
  const double yield_factor = options.prior.yield_pressure_factor;
  CalibrationResult result;
  result.hertz = options.hertz;
  result.law = options.prior;

  for (const CalibrationCase& data : cases) {
    if (data.overlaps.size() != data.forces.size())
      throw InputError(data.name, std::to_string(data.overlaps.size()) + " overlaps but " +
                                      std::to_string(data.forces.size()) + " forces: expected one force per overlap");
    const ContactConstants constants = case_contact_constants(data.body_i, data.body_j, options.hertz, options.prior);
    CaseCalibration entry;
    entry.name = data.name;
    entry.equivalent_radius = constants.equivalent_radius;
    entry.radius_ratio = constants.equivalent_radius / (mean_radius(data.body_i.semi_axes) + mean_radius(data.body_j.semi_axes));
    entry.yield_overlap = constants.yield_overlap;
    entry.yield_force = constants.yield_force;
    entry.profile = lambda_profile(constants, data.overlaps, data.forces);

    const double largest_overlap =
        data.overlaps.empty() ? 0.0 : *std::max_element(data.overlaps.begin(), data.overlaps.end());
    std::ostringstream where;
    where.precision(4);
    if (entry.profile.empty()) {
      where << "the data never leaves the elastic regime: its largest overlap " << largest_overlap
            << " µm does not exceed the elastic limit delta_Y = " << constants.yield_overlap << " µm by 2 %"
            << " (p0 = " << yield_factor << " Y, F_pY = " << constants.yield_force
            << " µN), so lambda_max, epsilon_max and n cannot be fitted; load well beyond delta_Y "
               "(the paper went to 15 % of r^I + r^J)";
      throw InputError(data.name, where.str());
    }
    if (entry.profile.size() < options.min_plastic_points) {
      where << "only " << entry.profile.size() << " loading points beyond delta_Y = " << constants.yield_overlap
            << " µm: expected at least " << options.min_plastic_points;
      throw InputError(data.name, where.str());
    }

    entry.own = fit_case(entry.profile, yield_factor);
    entry.own_exponent_fitted = exponent_identified(entry);
    if (!entry.own_exponent_fitted)  // n is not pinned by this case: the prior's n, as the paper fixed n = 1.8
      entry.own = fit_case(entry.profile, yield_factor, options.prior.fit.transition_exponent);
    entry.own_rms = rms_error(entry.profile, entry.own, yield_factor);
    // Elastic data beyond δ_Y: the force stays on the Hertz curve, and Hertz describes it as well
    // as the fitted law does. (Early in the transition the law itself is close to Hertz: data
    // loaded to 4 δ_Y deviates by only ~1.4 %, so closeness alone would reject it.)
    double deviation_sq = 0.0;
    for (const LambdaSample& sample : entry.profile) {
      const double hertz = constants.hertz_coefficient * sample.overlap * std::sqrt(sample.overlap);
      deviation_sq += (sample.force / hertz - 1.0) * (sample.force / hertz - 1.0);
    }
    const double hertz_deviation = std::sqrt(deviation_sq / static_cast<double>(entry.profile.size()));
    if (hertz_deviation < options.elastic_tolerance && hertz_deviation <= 1.25 * entry.own_rms + 0.001) {
      where << "the data never leaves the elastic regime: beyond delta_Y = " << constants.yield_overlap
            << " µm the force stays on the Hertz curve (RMS deviation " << format_percent(hertz_deviation)
            << " < " << format_percent(options.elastic_tolerance) << ", no worse than the fitted law's "
            << format_percent(entry.own_rms)
            << "), so there is no plastic transition to fit; is the material elastic-plastic?";
      throw InputError(data.name, where.str());
    }
    if (entry.own.lambda_max >= kLambdaMaxUpper * (1 - 1e-6) || entry.own.epsilon_max >= kEpsilonMaxUpper * (1 - 1e-6)) {
      where << "lambda_FEM of eq. (51) shows no plateau (the fit ran to lambda_max = " << entry.own.lambda_max
            << ", epsilon_max = " << entry.own.epsilon_max
            << "): the data looks elastic or stops long before the fully plastic regime";
      throw InputError(data.name, where.str());
    }
    if (entry.own.epsilon_max <= kEpsilonMaxLower * (1 + 1e-6)) {
      entry.transition_found = false;
      const LambdaSample& first = entry.profile.front();
      std::ostringstream warning;
      warning.precision(3);
      warning << data.name << ": eq. (28) finds no transition (epsilon_max at its bound 1): lambda_FEM does not rise "
              << "from " << yield_factor << "; near delta_Y the force is "
              << 100.0 * (first.force / (constants.hertz_coefficient * first.overlap * std::sqrt(first.overlap)) - 1.0)
              << " % off Hertz (check the FE mesh, the Hertz mode, or whether the geometry suits the law)";
      result.warnings.push_back(warning.str());
    }
    result.cases.push_back(std::move(entry));
  }

  result.exponent_fitted = fit_shared_exponent(result.cases, yield_factor, options.prior.fit.transition_exponent,
                                               result.law.fit.transition_exponent);
  if (!result.exponent_fitted)
    result.warnings.push_back("no case pins n (with n free, no fit reaches its lambda plateau inside the data, or n runs to a bound): n kept from the prior (" +
                              format_number(options.prior.fit.transition_exponent) + ")");
  std::vector<double> radius_ratios;
  std::vector<double> lambda_maxima;
  std::vector<double> epsilon_maxima;
  for (auto& entry : result.cases) {
    entry.shared_rms = rms_error(entry.profile, entry.shared, yield_factor);
    entry.plateau_reached = !entry.profile.empty() &&
                            entry.profile.back().contact_radius_ratio >= entry.shared.epsilon_max;
    if (!entry.plateau_reached) {
      std::ostringstream warning;
      warning.precision(4);
      warning << entry.name << ": the data ends at c_c/c_Y = " << entry.profile.back().contact_radius_ratio
              << ", before the fitted epsilon_max = " << entry.shared.epsilon_max
              << "; lambda_max and epsilon_max are extrapolated (load further to reach the plateau)";
      result.warnings.push_back(warning.str());
    }
    radius_ratios.push_back(entry.radius_ratio);
    lambda_maxima.push_back(entry.shared.lambda_max);
    epsilon_maxima.push_back(entry.shared.epsilon_max);
  }

  auto& fit = result.law.fit;
  const ExponentialFit lambda_fit =
      fit_exponential(radius_ratios, lambda_maxima, options.prior.fit.lambda_amplitude, options.prior.fit.lambda_rate);
  const ExponentialFit epsilon_fit = fit_exponential(radius_ratios, epsilon_maxima, options.prior.fit.epsilon_amplitude,
                                                     options.prior.fit.epsilon_rate);
  fit.lambda_amplitude = lambda_fit.amplitude;
  fit.lambda_rate = lambda_fit.rate;
  fit.lambda_offset = lambda_fit.offset;
  fit.epsilon_amplitude = epsilon_fit.amplitude;
  fit.epsilon_rate = epsilon_fit.rate;
  fit.epsilon_offset = epsilon_fit.offset;
  result.rates_fitted = lambda_fit.rate_fitted;
  result.amplitudes_fitted = lambda_fit.amplitude_fitted;
  if (!result.rates_fitted)
    result.warnings.push_back(std::string("fewer than 4 distinct R_e/r^ among the cases: o and t kept from the prior") +
                              (result.amplitudes_fitted ? "" : ", and m and s too"));
  if (std::abs(fit.lambda_rate) >= kRateBound * (1 - 1e-6) || std::abs(fit.epsilon_rate) >= kRateBound * (1 - 1e-6))
    result.warnings.push_back("an eq. (52) rate ran to its bound +-25: lambda_max or epsilon_max of the cases do not follow one exponential in R_e/r^ (see PREFIX_radius.png)");

  // The calibrated law as `ellc curve` evaluates it, against each case's loading data.
  for (std::size_t index = 0; index < cases.size(); ++index) {
    auto& entry = result.cases[index];
    const ContactConstants constants = case_contact_constants(cases[index].body_i, cases[index].body_j, options.hertz, result.law);
    double sum = 0.0;
    for (const LambdaSample& sample : entry.profile) {
      const double relative = loading_force(constants, sample.overlap).force / sample.force - 1.0;
      sum += relative * relative;
    }
    entry.model_rms = std::sqrt(sum / static_cast<double>(entry.profile.size()));
    if (const std::string error = validation_error(constants); !error.empty())
      result.warnings.push_back(entry.name + ": the calibrated constants give " + error);
  }
  return result;
}

std::string model_table_toml(const CalibrationResult& result) {
  std::ostringstream out;
  const auto& fit = result.law.fit;
  out << "# Transition constants calibrated by `ellc fit` (paper eq. 51, 28, 52) from " << result.cases.size()
      << " case(s).\n";
  out << "# case: R_e/r^, lambda_max, epsilon_max (shared n), own (lambda_max, epsilon_max, n), plateau reached,\n"
         "#       RMS relative force error of the calibrated law\n";
  char line[512];
  for (const auto& entry : result.cases) {
    std::snprintf(line, sizeof line, "#   %s: %.5g, %.5g, %.5g, (%.5g, %.5g, %.4g), %s, %.3g %%\n", entry.name.c_str(),
                  entry.radius_ratio, entry.shared.lambda_max, entry.shared.epsilon_max, entry.own.lambda_max,
                  entry.own.epsilon_max, entry.own.exponent, entry.plateau_reached ? "yes" : "no",
                  100.0 * entry.model_rms);
    out << line;
  }
  out << "# fitted: " << (result.amplitudes_fitted ? "m, " : "") << (result.rates_fitted ? "o, " : "") << "p, "
      << (result.amplitudes_fitted ? "s, " : "") << (result.rates_fitted ? "t, " : "") << "u"
      << (result.exponent_fitted ? ", n" : "") << "\n";
  for (const auto& warning : result.warnings) out << "# warning: " << warning << "\n";
  out << "[model]\n";
  out << "hertz = \"" << (result.hertz == HertzMode::exact ? "exact" : "hale") << "\"\n";
  const struct {
    const char* key;
    double value;
  } entries[] = {{"m", fit.lambda_amplitude},  {"o", fit.lambda_rate},  {"p", fit.lambda_offset},
                 {"s", fit.epsilon_amplitude}, {"t", fit.epsilon_rate}, {"u", fit.epsilon_offset},
                 {"n", fit.transition_exponent}, {"yield_pressure_factor", result.law.yield_pressure_factor}};
  for (const auto& [key, value] : entries) out << key << " = " << format_number(value) << "\n";
  return out.str();
}

}  // namespace ellc
