// Material layer: effective modulus (eq. 3), yield-stress mixing (docs/model.md §5), validation.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "ellc/material/material.hpp"
#include "support/nmc.hpp"

namespace {
using ellc::test::kNmc;

// E / (1 − ν²) of NMC, by hand.
constexpr double kNmcPlaneStrain = kNmc.youngs_modulus / (1.0 - kNmc.poisson_ratio * kNmc.poisson_ratio);

TEST(Material, IdenticalBodiesHalveThePlaneStrainModulus) {
  // E_e = E / (2 (1 − ν²)) for two equal bodies.
  EXPECT_NEAR(ellc::effective_modulus(kNmc, kNmc), kNmcPlaneStrain / 2.0, 1e-9);
}

TEST(Material, RigidPartnerLeavesTheSofterBodysModulus) {
  const ellc::Material rigid{1e300, 0.3, 1e300};
  EXPECT_NEAR(ellc::effective_modulus(kNmc, rigid), kNmcPlaneStrain, 1e-6);
}

TEST(Material, MixingIsSymmetricAndTakesTheSofterYieldStress) {
  const ellc::Material steel{210000.0, 0.3, 1000.0};
  const auto ij = ellc::mix(kNmc, steel);
  const auto ji = ellc::mix(steel, kNmc);
  EXPECT_DOUBLE_EQ(ij.effective_modulus, ji.effective_modulus);
  EXPECT_EQ(ij.yield_stress, 1000.0);
  EXPECT_EQ(ji.yield_stress, 1000.0);
}

TEST(Material, ValidationNamesTheFieldValueAndExpectation) {
  EXPECT_TRUE(ellc::validation_error(kNmc).empty());
  ellc::Material bad = kNmc;
  bad.poisson_ratio = 0.5;
  const std::string message = ellc::validation_error(bad, "body_I.material");
  EXPECT_NE(message.find("body_I.material.poisson_ratio = 0.5"), std::string::npos) << message;
  EXPECT_NE(message.find("(-1, 0.5)"), std::string::npos) << message;
  bad = kNmc;
  bad.youngs_modulus = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(ellc::validation_error(bad).find("youngs_modulus"), std::string::npos);
  bad = kNmc;
  bad.yield_stress = -1.0;
  EXPECT_NE(ellc::validation_error(bad).find("yield_stress = -1"), std::string::npos);
}
}  // namespace
