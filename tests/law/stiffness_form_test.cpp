// The stiffness_ratio form of the transition fits (transition_fit.hpp, issue 14): λ_max and ε_max of
// eq. (52) times (η/η_ref)^q with η = E_e/Y. Checked against the closed form written out here.

#include <gtest/gtest.h>

#include <cmath>

#include "ellc/law/contact_constants.hpp"
#include "support/nmc.hpp"

namespace {
using namespace ellc;

constexpr Material kAluminium{68900.0, 0.33, 276.0};  // 6061-T6, docs/materials.md

// Two spheres of radius 10 (R_e = 5, r̂^{I,J} = 20) of one material.
ContactConstants spheres(const Material& material, const LawParameters& law) {
  const PrincipalCurvatures sphere{0.1, 0.1};
  return make_contact_constants(mix(material, material), sphere, sphere, 0.0, 20.0, HertzMode::hale, law);
}

// E_e/Y by hand: E_e = E/(2(1 − ν²)) for two equal bodies (eq. 3).
double stiffness_ratio(const Material& m) {
  return m.youngs_modulus / (2.0 * (1.0 - m.poisson_ratio * m.poisson_ratio)) / m.yield_stress;
}

LawParameters stiffness_law(double q_lambda, double q_epsilon) {
  LawParameters law;
  law.fit.form = TransitionForm::stiffness_ratio;
  law.fit.lambda_stiffness_exponent = q_lambda;
  law.fit.epsilon_stiffness_exponent = q_epsilon;
  return law;
}

TEST(StiffnessForm, ReferenceIsNmcStiffnessRatio) {
  EXPECT_NEAR(kNmcStiffnessRatio, stiffness_ratio(test::kNmc), 1e-12 * kNmcStiffnessRatio);
}

TEST(StiffnessForm, PaperFormIgnoresTheMaterial) {
  const LawParameters paper;
  const double x = 0.25;                                    // R_e / r̂ of the sphere pair
  const double lambda = 1.05 * std::exp(-4.62 * x) + 2.42;  // eq. (53)
  const double epsilon = 8.19 * std::exp(-6.14 * x) + 1.14;
  for (const Material& material : {test::kNmc, kAluminium}) {
    const ContactConstants c = spheres(material, paper);
    EXPECT_NEAR(c.lambda_max, lambda, 1e-14);
    EXPECT_NEAR(c.epsilon_max, epsilon, 1e-14);
  }
}

TEST(StiffnessForm, AtTheReferenceMaterialItIsEquation52) {
  const ContactConstants paper = spheres(test::kNmc, LawParameters{});
  const ContactConstants scaled = spheres(test::kNmc, stiffness_law(0.3, 0.6));
  EXPECT_NEAR(scaled.lambda_max, paper.lambda_max, 1e-13);
  EXPECT_NEAR(scaled.epsilon_max, paper.epsilon_max, 1e-13);
  EXPECT_EQ(scaled.yield_overlap, paper.yield_overlap);
}

TEST(StiffnessForm, ScalesByAPowerOfTheStiffnessRatio) {
  const double q_lambda = 0.234;
  const double q_epsilon = 0.55;
  const ContactConstants paper = spheres(kAluminium, LawParameters{});
  const ContactConstants scaled = spheres(kAluminium, stiffness_law(q_lambda, q_epsilon));
  const double ratio = stiffness_ratio(kAluminium) / kNmcStiffnessRatio;  // ≈ 14.6
  EXPECT_NEAR(scaled.lambda_max, paper.lambda_max * std::pow(ratio, q_lambda), 1e-12);
  EXPECT_NEAR(scaled.epsilon_max, paper.epsilon_max * std::pow(ratio, q_epsilon), 1e-12);
  EXPECT_NEAR(scaled.plastic_limit_overlap / scaled.yield_overlap, std::pow(scaled.epsilon_max, 2), 1e-9);  // eq. (30)
  // A softer reference (η_ref = η of aluminium) makes aluminium the reference: eq. (52) again.
  LawParameters own_reference = stiffness_law(q_lambda, q_epsilon);
  own_reference.fit.reference_stiffness_ratio = stiffness_ratio(kAluminium);
  EXPECT_NEAR(spheres(kAluminium, own_reference).lambda_max, paper.lambda_max, 1e-12);
}

TEST(StiffnessForm, ThorntonVariantStaysAtTheYieldFactor) {
  const ContactConstants c = spheres(kAluminium, stiffness_law(0.5, 0.5).elastic_fully_plastic());
  EXPECT_DOUBLE_EQ(c.lambda_max, 1.6);
}

TEST(StiffnessForm, ValidationNamesTheReferenceRatio) {
  LawParameters law = stiffness_law(0.2, 0.4);
  EXPECT_EQ(validation_error(law), "");
  law.fit.reference_stiffness_ratio = -1.0;
  EXPECT_NE(validation_error(law).find("model.reference_stiffness_ratio = -1"), std::string::npos)
      << validation_error(law);
  law = stiffness_law(std::nan(""), 0.4);
  EXPECT_NE(validation_error(law).find("model.lambda_stiffness_exponent"), std::string::npos);
}

}  // namespace
