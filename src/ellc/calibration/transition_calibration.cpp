#include "ellc/calibration/transition_calibration.hpp"

#include <ceres/ceres.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <iterator>
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
      residuals[index] = sample.weight * (lambda_of(shape[0], shape[1], exponent[0], sample.contact_radius_ratio,
                                                    yield_pressure_factor) -
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

// The stiffness_ratio form: (a exp(r x) + b) exp(q ln(η/η_ref)) − y, one block per constant so
// that any of them can be held.
struct StiffnessFormResiduals {
  std::span<const double> x;
  std::vector<double> log_stiffness;  // ln(η/η_ref)
  std::span<const double> y;

  template <typename T>
  bool operator()(const T* const amplitude, const T* const rate, const T* const offset, const T* const exponent,
                  T* residuals) const {
    using std::exp;
    for (std::size_t index = 0; index < x.size(); ++index)
      residuals[index] =
          (amplitude[0] * exp(rate[0] * x[index]) + offset[0]) * exp(exponent[0] * log_stiffness[index]) - y[index];
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
    for (const std::size_t index : informative)
      shapes.push_back({cases[index].own.lambda_max, cases[index].own.epsilon_max});
    ceres::Problem problem;
    for (std::size_t slot = 0; slot < informative.size(); ++slot)
      add_case(problem, cases[informative[slot]].profile, yield_pressure_factor, shapes[slot].data(), &exponent);
    ceres::Solver::Summary summary;
    ceres::Solve(solver_options(), &problem, &summary);
    for (std::size_t slot = 0; slot < informative.size(); ++slot)
      cases[informative[slot]].shared = {shapes[slot][0], shapes[slot][1], exponent};
  }
  for (auto& entry : cases)
    if (!entry.own_exponent_fitted || informative.empty())
      entry.shared = fit_case(entry.profile, yield_pressure_factor, exponent);
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

// With the paper's form one material is fitted: every case's bodies must have the first case's
// materials. Throws naming the case file and the field that differs.
void require_one_material(const std::vector<CalibrationCase>& cases) {
  const CalibrationCase& first = cases.front();
  for (const CalibrationCase& data : cases) {
    const struct {
      const char* body;
      const Material& material;
      const Material& expected;
    } bodies[] = {{"body_I", data.body_i.material, first.body_i.material},
                  {"body_J", data.body_j.material, first.body_j.material}};
    for (const auto& [body, material, expected] : bodies) {
      const struct {
        const char* field;
        double value;
        double expected;
      } fields[] = {{"youngs_modulus", material.youngs_modulus, expected.youngs_modulus},
                    {"poisson_ratio", material.poisson_ratio, expected.poisson_ratio},
                    {"yield_stress", material.yield_stress, expected.yield_stress}};
      for (const auto& [field, value, wanted] : fields) {
        if (value == wanted) continue;
        const std::string source = data.case_path.empty() ? data.name : data.case_path + " (data " + data.name + ")";
        throw InputError(source, std::string(body) + ".material." + field + " = " + format_number(value) +
                                     " differs from " + format_number(wanted) + " of the first case (" +
                                     (first.case_path.empty() ? first.name : first.case_path) +
                                     "): expected one material per fit of the paper's form; fit several materials "
                                     "with --form stiffness_ratio");
      }
    }
  }
}

void require_converged(const ExponentialFit& fit, const char* quantity, std::size_t case_count, int max_iterations) {
  if (fit.converged) return;
  std::ostringstream out;
  out.precision(4);
  out << "the fit of " << quantity << " across the " << case_count << " cases (eq. 52) did not converge within "
      << max_iterations << " iterations (Ceres: " << fit.solver_report << "); RMS residual " << fit.rms
      << ": no [model] written";
  throw InputError("ellc fit", out.str());
}

}  // namespace

double profile_lambda(const TransitionPoint& point, double contact_radius_ratio,
                      double yield_pressure_factor) noexcept {
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

namespace {

// RMS of y − (amplitude exp(rate x) + offset) (η/η_ref)^q; log_stiffness empty: q ignored.
double form_rms(const ExponentialFit& fit, std::span<const double> x, std::span<const double> y,
                std::span<const double> log_stiffness = {}) {
  double sum = 0.0;
  for (std::size_t index = 0; index < x.size(); ++index) {
    const double factor = log_stiffness.empty() ? 1.0 : std::exp(fit.stiffness_exponent * log_stiffness[index]);
    const double residual = (fit.amplitude * std::exp(fit.rate * x[index]) + fit.offset) * factor - y[index];
    sum += residual * residual;
  }
  return x.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(x.size()));
}

// The multi-start of the eq. (52) rate: after the prior's (or the default) rate, these starts
// span the bounded range, so a fit does not stop in the local minimum nearest one guess.
constexpr double kRateStarts[] = {-20.0, -12.0, -8.0, -5.0, -3.0, -1.5, -0.5, 0.5, 2.0};

// Books one start's solve into `fit` (the first failure's message, converged if any start is) and
// says whether it is the best so far, lowering best_cost if so.
bool record_start(const ceres::Solver::Summary& summary, ExponentialFit& fit, double& best_cost) {
  const bool converged = summary.termination_type == ceres::CONVERGENCE && std::isfinite(summary.final_cost);
  if (!converged && fit.solver_report.empty()) fit.solver_report = summary.message;
  fit.converged = fit.converged || converged;
  if (!(std::isfinite(summary.final_cost) && summary.final_cost < best_cost * (1.0 - 1e-9))) return false;
  best_cost = summary.final_cost;
  return true;
}

}  // namespace

ExponentialFit fit_exponential(std::span<const double> x, std::span<const double> y, double fixed_amplitude,
                               double fixed_rate, int max_iterations) {
  ExponentialFit fit;
  const std::size_t distinct = distinct_count(x);
  if (distinct == 0) return fit;
  if (distinct == 1) {
    fit.amplitude = fixed_amplitude;
    fit.rate = fixed_rate;
    double sum = 0.0;
    for (std::size_t index = 0; index < x.size(); ++index)
      sum += y[index] - fixed_amplitude * std::exp(fixed_rate * x[index]);
    fit.offset = sum / static_cast<double>(x.size());
    fit.rms = form_rms(fit, x, y);
    return fit;
  }
  if (distinct < kDistinctForRate) {
    fit.rate = fixed_rate;
    std::tie(fit.amplitude, fit.offset) = linear_amplitude_offset(x, y, fixed_rate);
    fit.amplitude_fitted = true;
    fit.rms = form_rms(fit, x, y);
    return fit;
  }
  fit.amplitude_fitted = fit.rate_fitted = true;
  fit.converged = false;
  double best_cost = std::numeric_limits<double>::infinity();
  ceres::Solver::Options options = solver_options();
  options.max_num_iterations = max_iterations;
  std::vector<double> rate_starts{fixed_rate};
  rate_starts.insert(rate_starts.end(), std::begin(kRateStarts), std::end(kRateStarts));
  for (const double rate_start : rate_starts) {
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
    if (record_start(summary, fit, best_cost)) {
      fit.amplitude = parameters[0];
      fit.rate = parameters[1];
      fit.offset = parameters[2];
    }
  }
  fit.rms = form_rms(fit, x, y);
  return fit;
}

ExponentialFit fit_stiffness_form(std::span<const double> x, std::span<const double> stiffness_ratio,
                                  std::span<const double> y, double reference_stiffness_ratio,
                                  const ExponentialFit& prior, int max_iterations) {
  ExponentialFit fit = prior;
  fit.stiffness_exponent = 0.0;
  fit.rate_fitted = fit.amplitude_fitted = fit.stiffness_fitted = false;
  fit.converged = false;
  fit.solver_report.clear();
  std::vector<double> log_stiffness;
  log_stiffness.reserve(stiffness_ratio.size());
  bool off_reference = false;
  for (const double ratio : stiffness_ratio) {
    log_stiffness.push_back(std::log(ratio / reference_stiffness_ratio));
    off_reference = off_reference || std::abs(log_stiffness.back()) > 1e-9;
  }
  const std::size_t distinct_x = distinct_count(x);
  // One material only, away from the reference: its data cannot separate eq. (52) from the E/Y
  // factor, so eq. (52) stays the prior's (the reference material's) and only q is fitted.
  const bool single_material = distinct_count(stiffness_ratio) == 1;
  const bool fit_amplitude = !single_material && distinct_x >= 2;
  const bool fit_rate = !single_material && distinct_x >= kDistinctForRate;
  std::vector<double> rate_starts{prior.rate};
  if (fit_rate) rate_starts.insert(rate_starts.end(), std::begin(kRateStarts), std::end(kRateStarts));
  ceres::Solver::Options options = solver_options();
  options.max_num_iterations = max_iterations;
  double best_cost = std::numeric_limits<double>::infinity();
  for (const double rate_start : rate_starts) {
    double amplitude = prior.amplitude;
    double rate = rate_start;
    double offset = prior.offset;
    double exponent = 0.0;
    if (fit_amplitude) std::tie(amplitude, offset) = linear_amplitude_offset(x, y, rate);
    ceres::Problem problem;
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<StiffnessFormResiduals, ceres::DYNAMIC, 1, 1, 1, 1>(
                                 new StiffnessFormResiduals{x, log_stiffness, y}, static_cast<int>(x.size())),
                             nullptr, &amplitude, &rate, &offset, &exponent);
    if (!fit_amplitude) problem.SetParameterBlockConstant(&amplitude);
    if (!fit_rate) {
      problem.SetParameterBlockConstant(&rate);
    } else {
      problem.SetParameterLowerBound(&rate, 0, -kRateBound);
      problem.SetParameterUpperBound(&rate, 0, kRateBound);
    }
    if (single_material) problem.SetParameterBlockConstant(&offset);
    if (!off_reference) problem.SetParameterBlockConstant(&exponent);
    ceres::Solver::Summary summary;
    ceres::Solve(options, &problem, &summary);
    if (record_start(summary, fit, best_cost)) {
      fit.amplitude = amplitude;
      fit.rate = rate;
      fit.offset = offset;
      fit.stiffness_exponent = exponent;
    }
  }
  fit.amplitude_fitted = fit_amplitude;
  fit.rate_fitted = fit_rate;
  fit.stiffness_fitted = off_reference;
  fit.rms = form_rms(fit, x, y, log_stiffness);
  return fit;
}

CalibrationResult calibrate(const std::vector<CalibrationCase>& cases, const CalibrationOptions& options) {
  if (cases.empty()) throw InputError("", "no calibration cases: expected at least one CSV of overlap and force");
  if (options.form == TransitionForm::paper) require_one_material(cases);
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
    entry.radius_ratio =
        constants.equivalent_radius / (mean_radius(data.body_i.semi_axes) + mean_radius(data.body_j.semi_axes));
    entry.yield_overlap = constants.yield_overlap;
    entry.yield_force = constants.yield_force;
    entry.stiffness_ratio = constants.effective_modulus / constants.yield_stress;
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
            << " µm the force stays on the Hertz curve (RMS deviation " << format_percent(hertz_deviation) << " < "
            << format_percent(options.elastic_tolerance) << ", no worse than the fitted law's "
            << format_percent(entry.own_rms)
            << "), so there is no plastic transition to fit; is the material elastic-plastic?";
      throw InputError(data.name, where.str());
    }
    if (entry.own.lambda_max >= kLambdaMaxUpper * (1 - 1e-6) ||
        entry.own.epsilon_max >= kEpsilonMaxUpper * (1 - 1e-6)) {
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

  // Form stiffness_ratio with one material away from the reference: eq. (52) and n stay the
  // prior's (the reference material's law is kept), each case's λ_max, ε_max are fitted with that n.
  std::vector<double> case_stiffness_ratios;
  case_stiffness_ratios.reserve(result.cases.size());
  for (const auto& entry : result.cases) case_stiffness_ratios.push_back(entry.stiffness_ratio);
  const bool anchored = options.form == TransitionForm::stiffness_ratio && distinct_count(case_stiffness_ratios) == 1;
  result.anchored = anchored;
  if (anchored) {
    for (auto& entry : result.cases)
      entry.shared = fit_case(entry.profile, yield_factor, options.prior.fit.transition_exponent);
    result.law.fit.transition_exponent = options.prior.fit.transition_exponent;
  } else {
    result.exponent_fitted = fit_shared_exponent(result.cases, yield_factor, options.prior.fit.transition_exponent,
                                                 result.law.fit.transition_exponent);
  }
  if (!result.exponent_fitted && !anchored)
    result.warnings.push_back(
        "no case pins n (with n free, no fit reaches its lambda plateau inside the data, or n runs to a bound): n kept "
        "from the prior (" +
        format_number(options.prior.fit.transition_exponent) + ")");
  std::vector<double> radius_ratios;
  std::vector<double> lambda_maxima;
  std::vector<double> epsilon_maxima;
  for (auto& entry : result.cases) {
    entry.shared_rms = rms_error(entry.profile, entry.shared, yield_factor);
    entry.plateau_reached =
        !entry.profile.empty() && entry.profile.back().contact_radius_ratio >= entry.shared.epsilon_max;
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
  ExponentialFit lambda_fit;
  ExponentialFit epsilon_fit;
  if (options.form == TransitionForm::stiffness_ratio) {
    const std::vector<double>& stiffness_ratios = case_stiffness_ratios;
    const double reference = options.prior.fit.reference_stiffness_ratio;
    const auto [lowest, highest] = std::minmax_element(stiffness_ratios.begin(), stiffness_ratios.end());
    if (std::abs(std::log(*lowest / reference)) <= 1e-9 && std::abs(std::log(*highest / reference)) <= 1e-9)
      throw InputError("ellc fit", "form stiffness_ratio: every case has E_e/Y = " + format_number(*lowest) +
                                       ", the reference material's (reference_stiffness_ratio): the E_e/Y exponents "
                                       "cannot be fitted; add data of a second material, or fit the paper's form");
    const auto& prior = options.prior.fit;
    ExponentialFit lambda_prior;
    lambda_prior.amplitude = prior.lambda_amplitude;
    lambda_prior.rate = prior.lambda_rate;
    lambda_prior.offset = prior.lambda_offset;
    ExponentialFit epsilon_prior;
    epsilon_prior.amplitude = prior.epsilon_amplitude;
    epsilon_prior.rate = prior.epsilon_rate;
    epsilon_prior.offset = prior.epsilon_offset;
    lambda_fit = fit_stiffness_form(radius_ratios, stiffness_ratios, lambda_maxima, reference, lambda_prior,
                                    options.max_iterations);
    epsilon_fit = fit_stiffness_form(radius_ratios, stiffness_ratios, epsilon_maxima, reference, epsilon_prior,
                                     options.max_iterations);
    fit.form = TransitionForm::stiffness_ratio;
    fit.reference_stiffness_ratio = reference;
    fit.lambda_stiffness_exponent = lambda_fit.stiffness_exponent;
    fit.epsilon_stiffness_exponent = epsilon_fit.stiffness_exponent;
    result.stiffness_fitted = true;
    std::ostringstream range;
    range.precision(4);
    range << "the E_e/Y factor was fitted over E_e/Y = " << std::min(*lowest, reference) << " .. "
          << std::max(*highest, reference) << " (reference " << reference << "); outside it is an extrapolation";
    result.warnings.push_back(range.str());
    if (anchored)
      result.warnings.push_back(
          "one material only: m, o, p, s, t, u and n kept from the prior (the reference "
          "material's), only the E_e/Y exponents fitted");
  } else {
    lambda_fit = fit_exponential(radius_ratios, lambda_maxima, options.prior.fit.lambda_amplitude,
                                 options.prior.fit.lambda_rate, options.max_iterations);
    epsilon_fit = fit_exponential(radius_ratios, epsilon_maxima, options.prior.fit.epsilon_amplitude,
                                  options.prior.fit.epsilon_rate, options.max_iterations);
  }
  require_converged(lambda_fit, "lambda_max", result.cases.size(), options.max_iterations);
  require_converged(epsilon_fit, "epsilon_max", result.cases.size(), options.max_iterations);
  result.lambda_rms = lambda_fit.rms;
  result.epsilon_rms = epsilon_fit.rms;
  fit.lambda_amplitude = lambda_fit.amplitude;
  fit.lambda_rate = lambda_fit.rate;
  fit.lambda_offset = lambda_fit.offset;
  fit.epsilon_amplitude = epsilon_fit.amplitude;
  fit.epsilon_rate = epsilon_fit.rate;
  fit.epsilon_offset = epsilon_fit.offset;
  result.rates_fitted = lambda_fit.rate_fitted;
  result.amplitudes_fitted = lambda_fit.amplitude_fitted;
  if (!result.rates_fitted && !(result.stiffness_fitted && !result.amplitudes_fitted))
    result.warnings.push_back(std::string("fewer than 4 distinct R_e/r^ among the cases: o and t kept from the prior") +
                              (result.amplitudes_fitted ? "" : ", and m and s too"));
  if (std::abs(fit.lambda_rate) >= kRateBound * (1 - 1e-6) || std::abs(fit.epsilon_rate) >= kRateBound * (1 - 1e-6))
    result.warnings.push_back(
        "an eq. (52) rate ran to its bound +-25: lambda_max or epsilon_max of the cases do not follow one exponential "
        "in R_e/r^ (see PREFIX_radius.png)");

  // The calibrated law as `ellc curve` evaluates it, against each case's loading data.
  for (std::size_t index = 0; index < cases.size(); ++index) {
    auto& entry = result.cases[index];
    const ContactConstants constants =
        case_contact_constants(cases[index].body_i, cases[index].body_j, options.hertz, result.law);
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
    std::snprintf(line, sizeof line, "#   %s: %.5g, %.5g, %.5g, (%.5g, %.5g, %.4g), %s, %.3g %%", entry.name.c_str(),
                  entry.radius_ratio, entry.shared.lambda_max, entry.shared.epsilon_max, entry.own.lambda_max,
                  entry.own.epsilon_max, entry.own.exponent, entry.plateau_reached ? "yes" : "no",
                  100.0 * entry.model_rms);
    out << line;
    if (result.stiffness_fitted) {
      std::snprintf(line, sizeof line, ", E_e/Y = %.4g", entry.stiffness_ratio);
      out << line;
    }
    out << "\n";
  }
  if (result.anchored) {
    out << "# fitted: the E_e/Y exponents only (m, o, p, s, t, u, n are the prior's)\n";
  } else {
    out << "# fitted: " << (result.amplitudes_fitted ? "m, " : "") << (result.rates_fitted ? "o, " : "") << "p, "
        << (result.amplitudes_fitted ? "s, " : "") << (result.rates_fitted ? "t, " : "") << "u"
        << (result.exponent_fitted ? ", n" : "") << (result.stiffness_fitted ? ", E_e/Y exponents" : "") << "\n";
  }
  for (const auto& warning : result.warnings) out << "# warning: " << warning << "\n";
  out << "[model]\n";
  out << "hertz = \"" << (result.hertz == HertzMode::exact ? "exact" : "hale") << "\"\n";
  const struct {
    const char* key;
    double value;
  } entries[] = {{"m", fit.lambda_amplitude},    {"o", fit.lambda_rate},
                 {"p", fit.lambda_offset},       {"s", fit.epsilon_amplitude},
                 {"t", fit.epsilon_rate},        {"u", fit.epsilon_offset},
                 {"n", fit.transition_exponent}, {"yield_pressure_factor", result.law.yield_pressure_factor}};
  for (const auto& [key, value] : entries) out << key << " = " << format_number(value) << "\n";
  if (fit.form == TransitionForm::stiffness_ratio) {
    out << "form = \"stiffness_ratio\"  # lambda_max, epsilon_max x (E_e/Y / reference_stiffness_ratio)^exponent\n";
    out << "lambda_stiffness_exponent = " << format_number(fit.lambda_stiffness_exponent) << "\n";
    out << "epsilon_stiffness_exponent = " << format_number(fit.epsilon_stiffness_exponent) << "\n";
    out << "reference_stiffness_ratio = " << format_number(fit.reference_stiffness_ratio) << "\n";
  }
  return out.str();
}

}  // namespace ellc
