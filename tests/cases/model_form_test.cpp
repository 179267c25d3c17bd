// [model] form = "stiffness_ratio" (issue 14): reading, and the bad input it rejects by name.

#include <gtest/gtest.h>

#include <string>

#include "ellc/cases/case_file.hpp"
#include "support/input_error.hpp"

namespace {
using namespace ellc;

const std::string kCase =
    "[material]\nyoungs_modulus = 68900.0\npoisson_ratio = 0.33\nyield_stress = 276.0\n"
    "[body_I]\nsemi_axes = [10.0, 10.0, 10.0]\n[body_J]\nsemi_axes = [10.0, 10.0, 10.0]\n"
    "[protocol]\nwaypoints = [0.0, 0.5]\n";

std::string error_of(const std::string& model) {
  return test::input_error_message([&] { (void)parse_curve_case(kCase + "[model]\n" + model, "case.toml"); });
}

TEST(ModelForm, PaperIsTheDefault) {
  const CurveCase result = parse_curve_case(kCase + "[model]\nm = 1.0\n", "case.toml");
  EXPECT_EQ(result.model.law.fit.form, TransitionForm::paper);
  EXPECT_EQ(result.model.law.fit.lambda_stiffness_exponent, 0.0);
}

TEST(ModelForm, StiffnessRatioReadsItsExponents) {
  const CurveCase result = parse_curve_case(kCase +
                                                "[model]\nform = \"stiffness_ratio\"\nlambda_stiffness_exponent = "
                                                "0.25\nepsilon_stiffness_exponent = 0.5\n",
                                            "case.toml");
  const TransitionFit& fit = result.model.law.fit;
  EXPECT_EQ(fit.form, TransitionForm::stiffness_ratio);
  EXPECT_EQ(fit.lambda_stiffness_exponent, 0.25);
  EXPECT_EQ(fit.epsilon_stiffness_exponent, 0.5);
  EXPECT_EQ(fit.reference_stiffness_ratio, kNmcStiffnessRatio);
  const CurveCase own = parse_curve_case(kCase +
                                             "[model]\nform = \"stiffness_ratio\"\nlambda_stiffness_exponent = 0.25\n"
                                             "epsilon_stiffness_exponent = 0.5\nreference_stiffness_ratio = 140.0\n",
                                         "case.toml");
  EXPECT_EQ(own.model.law.fit.reference_stiffness_ratio, 140.0);
}

TEST(ModelForm, FormWithoutItsCoefficientsNamesTheMissingKey) {
  std::string message = error_of("form = \"stiffness_ratio\"\n");
  EXPECT_NE(message.find("model.lambda_stiffness_exponent"), std::string::npos) << message;
  EXPECT_NE(message.find("missing"), std::string::npos) << message;
  message = error_of("form = \"stiffness_ratio\"\nlambda_stiffness_exponent = 0.2\n");
  EXPECT_NE(message.find("model.epsilon_stiffness_exponent"), std::string::npos) << message;
}

TEST(ModelForm, CoefficientsWithoutTheFormAreRejected) {
  const std::string message = error_of("lambda_stiffness_exponent = 0.2\n");
  EXPECT_NE(message.find("model.lambda_stiffness_exponent"), std::string::npos) << message;
  EXPECT_NE(message.find("form = \"stiffness_ratio\""), std::string::npos) << message;
}

TEST(ModelForm, UnknownFormAndBadReferenceAreRejected) {
  EXPECT_NE(error_of("form = \"johnson\"\n").find("model.form"), std::string::npos);
  const std::string message = error_of(
      "form = \"stiffness_ratio\"\nlambda_stiffness_exponent = 0.2\nepsilon_stiffness_exponent = 0.4\n"
      "reference_stiffness_ratio = 0.0\n");
  EXPECT_NE(message.find("model.reference_stiffness_ratio = 0"), std::string::npos) << message;
}

}  // namespace
