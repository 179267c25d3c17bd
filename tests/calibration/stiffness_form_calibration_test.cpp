// `ellc fit` over several materials (issue 14): the stiffness_ratio form recovered from data made
// by the law itself, and the bad input of a multi-material fit.

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "calibration_support.hpp"
#include "ellc/calibration/transition_calibration.hpp"
#include "ellc/io/input_error.hpp"
#include "support/input_error.hpp"

namespace ellc {
namespace {

using testing_support::body;
using testing_support::true_law;

constexpr Material kAluminium{68900.0, 0.33, 276.0};  // 6061-T6, docs/materials.md
constexpr Material kCopper{117000.0, 0.34, 70.0};     // annealed copper, E_e/Y ≈ 940

double relative(double value, double expected) { return std::abs(value / expected - 1.0); }

// The law with known constants in the stiffness_ratio form (q deliberately not the fitted FE values).
LawParameters true_stiffness_law() {
  LawParameters law = true_law();
  law.fit.form = TransitionForm::stiffness_ratio;
  law.fit.lambda_stiffness_exponent = 0.2;
  law.fit.epsilon_stiffness_exponent = 0.45;
  return law;
}

// Loading data of the law for one geometry and material, to 1.5 δ_max in 40 points.
CalibrationCase law_case(const std::string& name, const Eigen::Vector3d& aspect_i, const Eigen::Vector3d& aspect_j,
                         const Material& material, const LawParameters& law, double noise = 0.0, unsigned seed = 1) {
  CalibrationCase data;
  data.name = name;
  data.case_path = name + ".toml";
  data.body_i = body(aspect_i);
  data.body_j = body(aspect_j);
  data.body_i.material = data.body_j.material = material;
  const ContactConstants constants = case_contact_constants(data.body_i, data.body_j, HertzMode::hale, law);
  std::mt19937 generator(seed);
  std::normal_distribution<double> normal;
  for (int step = 1; step <= 40; ++step) {
    const double overlap = 1.5 * constants.plastic_limit_overlap * step / 40;
    data.overlaps.push_back(overlap);
    data.forces.push_back(loading_force(constants, overlap).force * (1.0 + noise * normal(generator)));
  }
  return data;
}

// Six NMC geometries (they fix eq. 52) and three aluminium ones (they fix q).
std::vector<CalibrationCase> two_materials(const LawParameters& law, double noise = 0.0) {
  std::vector<CalibrationCase> cases;
  const std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> shapes = {
      {{1, 1, 1}, {1, 1, 1}}, {{1, 1, 0.8}, {1, 1.25, 1.25}}, {{1, 0.66, 0.66}, {1, 0.66, 0.66}},
      {{1, 2, 2}, {1, 2, 2}}, {{1, 0.5, 0.5}, {1, 0.5, 0.5}}, {{1, 1.5, 1.5}, {1, 0.8, 0.8}}};
  unsigned seed = 1;
  for (std::size_t index = 0; index < shapes.size(); ++index)
    cases.push_back(law_case("nmc" + std::to_string(index), shapes[index].first, shapes[index].second, test::kNmc, law,
                             noise, seed++));
  for (std::size_t index : {0U, 2U, 4U})
    cases.push_back(law_case("al" + std::to_string(index), shapes[index].first, shapes[index].second, kAluminium, law,
                             noise, seed++));
  return cases;
}

CalibrationOptions stiffness_options() {
  CalibrationOptions options;
  options.form = TransitionForm::stiffness_ratio;
  return options;
}

TEST(StiffnessFormCalibration, NoiseFreeDataOfTwoMaterialsGivesTheConstantsBack) {
  const LawParameters truth = true_stiffness_law();
  const CalibrationResult result = calibrate(two_materials(truth), stiffness_options());
  const TransitionFit& fit = result.law.fit;
  EXPECT_EQ(fit.form, TransitionForm::stiffness_ratio);
  EXPECT_TRUE(result.stiffness_fitted);
  EXPECT_TRUE(result.rates_fitted);
  EXPECT_LT(std::abs(fit.lambda_stiffness_exponent - 0.2), 1e-3);
  EXPECT_LT(std::abs(fit.epsilon_stiffness_exponent - 0.45), 2e-3);
  EXPECT_LT(relative(fit.lambda_offset, truth.fit.lambda_offset), 1e-3);
  EXPECT_LT(relative(fit.epsilon_offset, truth.fit.epsilon_offset), 2e-3);
  EXPECT_EQ(fit.reference_stiffness_ratio, kNmcStiffnessRatio);
  for (const auto& entry : result.cases) EXPECT_LT(entry.model_rms, 1e-3) << entry.name;
  // The [model] table carries the form and reads back as the same law.
  const std::string table = model_table_toml(result);
  EXPECT_NE(table.find("form = \"stiffness_ratio\""), std::string::npos) << table;
  EXPECT_NE(table.find("lambda_stiffness_exponent = "), std::string::npos);
}

TEST(StiffnessFormCalibration, NoisyDataStaysWithinTheStatedTolerance) {
  const CalibrationResult result = calibrate(two_materials(true_stiffness_law(), 0.01), stiffness_options());
  // λ_max, ε_max at aluminium's stiffness ratio over the geometries' R_e/r̂ (docs/calibration.md).
  const double eta = 68900.0 / (2.0 * (1.0 - 0.33 * 0.33)) / 276.0;
  const TransitionFit truth = true_stiffness_law().fit;
  for (double x = 0.1; x <= 0.6; x += 0.05) {
    EXPECT_LT(relative(result.law.fit.lambda_max_for(x, eta), truth.lambda_max_for(x, eta)), 0.03) << x;
    EXPECT_LT(relative(result.law.fit.epsilon_max_for(x, eta), truth.epsilon_max_for(x, eta)), 0.12) << x;
  }
}

TEST(StiffnessFormCalibration, OneOtherMaterialFitsOnlyTheExponents) {
  // Aluminium data alone, made with the paper's eq. (53) at NMC times (η/η_ref)^q.
  LawParameters truth;
  truth.fit.form = TransitionForm::stiffness_ratio;
  truth.fit.lambda_stiffness_exponent = 0.25;
  truth.fit.epsilon_stiffness_exponent = 0.5;
  std::vector<CalibrationCase> cases = {law_case("al_sphere", {1, 1, 1}, {1, 1, 1}, kAluminium, truth),
                                        law_case("al_slim", {1, 0.5, 0.5}, {1, 0.5, 0.5}, kAluminium, truth)};
  const CalibrationResult result = calibrate(cases, stiffness_options());
  EXPECT_FALSE(result.amplitudes_fitted);
  EXPECT_EQ(result.law.fit.lambda_amplitude, LawParameters{}.fit.lambda_amplitude);
  EXPECT_EQ(result.law.fit.epsilon_offset, LawParameters{}.fit.epsilon_offset);
  EXPECT_LT(std::abs(result.law.fit.lambda_stiffness_exponent - 0.25), 2e-3);
  EXPECT_LT(std::abs(result.law.fit.epsilon_stiffness_exponent - 0.5), 5e-3);
}

TEST(StiffnessFormCalibration, PaperFormRejectsASecondMaterialNamingFileAndField) {
  std::vector<CalibrationCase> cases = two_materials(true_law());
  const std::string message = test::input_error_message([&] { (void)calibrate(cases); });
  EXPECT_NE(message.find("al0.toml"), std::string::npos) << message;
  EXPECT_NE(message.find("body_I.material.youngs_modulus = 68900"), std::string::npos) << message;
  EXPECT_NE(message.find("--form stiffness_ratio"), std::string::npos) << message;
  // Only the yield stress differs: named too.
  Material harder = test::kNmc;
  harder.yield_stress = 9000.0;
  cases = {law_case("a", {1, 1, 1}, {1, 1, 1}, test::kNmc, true_law()),
           law_case("b", {1, 1, 1}, {1, 1, 1}, harder, true_law())};
  EXPECT_NE(test::input_error_message([&] { (void)calibrate(cases); }).find("yield_stress = 9000"), std::string::npos);
}

TEST(StiffnessFormCalibration, ReferenceMaterialAloneCannotFitTheExponents) {
  const std::vector<CalibrationCase> cases = testing_support::synthetic_set(0.0, 1);
  const std::string message = test::input_error_message([&] { (void)calibrate(cases, stiffness_options()); });
  EXPECT_NE(message.find("every case has E_e/Y = "), std::string::npos) << message;
}

TEST(StiffnessFormCalibration, NonConvergingFitSaysSoWithTheResidual) {
  CalibrationOptions options = stiffness_options();
  options.max_iterations = 1;
  const std::vector<CalibrationCase> cases = two_materials(true_stiffness_law(), 0.01);
  const std::string message = test::input_error_message([&] { (void)calibrate(cases, options); });
  EXPECT_NE(message.find("did not converge"), std::string::npos) << message;
  EXPECT_NE(message.find("RMS residual"), std::string::npos) << message;
  EXPECT_NE(message.find("no [model] written"), std::string::npos) << message;
  // The paper's form says the same.
  CalibrationOptions paper;
  paper.max_iterations = 1;
  const std::string paper_message =
      test::input_error_message([&] { (void)calibrate(testing_support::synthetic_set(0.01, 3), paper); });
  EXPECT_NE(paper_message.find("did not converge"), std::string::npos) << paper_message;
}

TEST(StiffnessFormCalibration, FarSofterMaterialExtrapolatesAndIsReported) {
  std::vector<CalibrationCase> cases = two_materials(true_stiffness_law());
  cases.push_back(law_case("cu", {1, 1, 1}, {1, 1, 1}, kCopper, true_stiffness_law()));
  const CalibrationResult result = calibrate(cases, stiffness_options());
  bool range_reported = false;
  for (const auto& warning : result.warnings) range_reported |= warning.find("fitted over E_e/Y") != std::string::npos;
  EXPECT_TRUE(range_reported);
  EXPECT_LT(std::abs(result.law.fit.lambda_stiffness_exponent - 0.2), 2e-3);
}

}  // namespace
}  // namespace ellc
