// Calibration of the transition fits (eq. 51, 28, 52) against data made by the law itself.

#include <gtest/gtest.h>

#include <cmath>

#include "calibration_support.hpp"
#include "ellc/calibration/transition_calibration.hpp"
#include "ellc/io/input_error.hpp"
#include "ellc/io/table_reader.hpp"
#include "support/input_error.hpp"

namespace ellc {
namespace {

using testing_support::synthetic_case;
using testing_support::synthetic_set;
using testing_support::true_law;

double relative(double value, double expected) { return std::abs(value / expected - 1.0); }

TEST(Calibration, NoiseFreeDataGivesTheConstantsBack) {
  const CalibrationResult result = calibrate(synthetic_set(0.0, 1));
  const TransitionFit& fit = result.law.fit;
  const TransitionFit truth = true_law().fit;
  EXPECT_TRUE(result.rates_fitted);
  EXPECT_TRUE(result.exponent_fitted);
  EXPECT_LT(relative(fit.lambda_amplitude, truth.lambda_amplitude), 1e-3);
  EXPECT_LT(relative(fit.lambda_rate, truth.lambda_rate), 1e-3);
  EXPECT_LT(relative(fit.lambda_offset, truth.lambda_offset), 1e-3);
  EXPECT_LT(relative(fit.epsilon_amplitude, truth.epsilon_amplitude), 1e-3);
  EXPECT_LT(relative(fit.epsilon_rate, truth.epsilon_rate), 1e-3);
  EXPECT_LT(relative(fit.epsilon_offset, truth.epsilon_offset), 1e-3);
  EXPECT_LT(relative(fit.transition_exponent, truth.transition_exponent), 1e-3);
  for (const auto& entry : result.cases) {
    EXPECT_TRUE(entry.plateau_reached) << entry.name;
    EXPECT_LT(entry.model_rms, 1e-4) << entry.name;
  }
}

// Stated tolerance (docs/calibration.md): with 1 % force noise, λ_max(x) of eq. (52) within
// 1.5 % and ε_max(x) within 8 % over the cases' range of R_e/r̂, n within 15 %.
TEST(Calibration, OnePercentNoiseRecoversTheFitFunctions) {
  const CalibrationResult result = calibrate(synthetic_set(0.01, 7));
  const TransitionFit truth = true_law().fit;
  for (double x = 0.10; x <= 0.63; x += 0.01) {
    EXPECT_LT(relative(result.law.fit.lambda_max(x), truth.lambda_max(x)), 0.015) << x;
    EXPECT_LT(relative(result.law.fit.epsilon_max(x), truth.epsilon_max(x)), 0.08) << x;
  }
  EXPECT_LT(relative(result.law.fit.transition_exponent, truth.transition_exponent), 0.15);
  for (const auto& entry : result.cases) EXPECT_LT(entry.model_rms, 0.015) << entry.name;
}

TEST(Calibration, ElasticDataIsRejectedWithAClearMessage) {
  CalibrationCase data = synthetic_case("elastic", {1, 1, 1}, {1, 1, 1}, 0.0, 1);
  const ContactConstants constants = case_contact_constants(data.body_i, data.body_j, HertzMode::hale, {});
  for (double& overlap : data.overlaps) overlap *= 0.9 * constants.yield_overlap / data.overlaps.back();
  const std::string message = test::input_error_message([&] { (void)calibrate({data}); });
  ASSERT_FALSE(message.empty()) << "elastic data was accepted";
  EXPECT_NE(message.find("elastic: the data never leaves the elastic regime"), std::string::npos) << message;
  EXPECT_NE(message.find("delta_Y"), std::string::npos) << message;
}

TEST(Calibration, HertzDataBeyondYieldIsRejected) {
  CalibrationCase data = synthetic_case("hertz", {1, 1, 0.8}, {1, 1.25, 1.25}, 0.0, 1);
  const ContactConstants constants = case_contact_constants(data.body_i, data.body_j, HertzMode::hale, {});
  for (std::size_t index = 0; index < data.overlaps.size(); ++index)
    data.forces[index] = constants.hertz_coefficient * std::pow(data.overlaps[index], 1.5);
  EXPECT_THROW((void)calibrate({data}), InputError);
}

TEST(Calibration, DataStoppingBeforeThePlateauKeepsThePriorExponent) {
  // Loaded to half of δ_max only: λ never flattens, so n cannot be pinned.
  const std::vector<CalibrationCase> cases{synthetic_case("short", {1, 1, 1}, {1, 1, 1}, 0.0, 1, true_law(), 30, 0.5)};
  const CalibrationResult result = calibrate(cases);
  EXPECT_FALSE(result.exponent_fitted);
  EXPECT_DOUBLE_EQ(result.law.fit.transition_exponent, LawParameters{}.fit.transition_exponent);
  EXPECT_FALSE(result.cases[0].plateau_reached);
  EXPECT_GE(result.warnings.size(), 2u);  // n kept, extrapolated, rates kept
}

TEST(Calibration, UnloadingPointsAreNotPartOfTheProfile) {
  CalibrationCase data = synthetic_case("cycle", {1, 1, 1}, {1, 1, 1}, 0.0, 1);
  const ContactConstants constants = case_contact_constants(data.body_i, data.body_j, HertzMode::hale, true_law());
  const std::size_t loaded = data.overlaps.size();
  const std::vector<LambdaSample> before = lambda_profile(constants, data.overlaps, data.forces);
  for (int step = 1; step <= 5; ++step) {  // unload part way: not the envelope
    const double overlap = data.overlaps[loaded - 1] * (1.0 - 0.1 * step);
    data.overlaps.push_back(overlap);
    data.forces.push_back(evaluate_contact(constants, overlap, data.overlaps[loaded - 1]).force);
  }
  EXPECT_EQ(lambda_profile(constants, data.overlaps, data.forces).size(), before.size());
  // Eq. (51) on the law's own forces is the law's λ.
  for (const LambdaSample& sample : before)
    EXPECT_NEAR(sample.lambda, transition_lambda(constants, sample.contact_radius_ratio * constants.yield_contact_radius),
                1e-9);
}

TEST(Calibration, ModelTableReadsBackAsTheModel) {
  const CalibrationResult result = calibrate(synthetic_set(0.0, 3));
  const std::string text = model_table_toml(result);
  const toml::table root = parse_toml_text(text, "fit.toml");
  TableReader reader(root, "", "fit.toml");
  auto model_table = reader.table("model");
  const ModelSpec model = read_model(model_table);
  EXPECT_EQ(model.law.fit.lambda_amplitude, result.law.fit.lambda_amplitude);
  EXPECT_EQ(model.law.fit.epsilon_rate, result.law.fit.epsilon_rate);
  EXPECT_EQ(model.law.fit.transition_exponent, result.law.fit.transition_exponent);
  EXPECT_EQ(model.hertz, HertzMode::hale);
}

TEST(Calibration, ExponentialFitFallsBackWithFewPoints) {
  const std::vector<double> x{0.2};
  const std::vector<double> y{3.0};
  const ExponentialFit one = fit_exponential(x, y, 1.0, -4.0);
  EXPECT_FALSE(one.amplitude_fitted);
  EXPECT_NEAR(one.amplitude * std::exp(one.rate * 0.2) + one.offset, 3.0, 1e-12);
  const std::vector<double> x2{0.1, 0.5};
  const std::vector<double> y2{3.0, 2.5};
  const ExponentialFit two = fit_exponential(x2, y2, 1.0, -4.0);
  EXPECT_TRUE(two.amplitude_fitted);
  EXPECT_FALSE(two.rate_fitted);
  EXPECT_NEAR(two.amplitude * std::exp(-0.4) + two.offset, 3.0, 1e-12);
  EXPECT_NEAR(two.amplitude * std::exp(-2.0) + two.offset, 2.5, 1e-12);
}

}  // namespace
}  // namespace ellc
