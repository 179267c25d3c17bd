// Viscous damping and the damped normal force (src/ellc/contact/normal_damping.hpp).
#include <gtest/gtest.h>

#include <cmath>

#include "ellc/contact/normal_damping.hpp"

namespace {
using namespace ellc;

TEST(NormalDamping, UnitRatioIsCriticalDamping) {
  // m ẍ + c ẋ + k x = 0 is critically damped when c² = 4 m k.
  for (const double mass : {1e-3, 0.7, 42.0}) {
    for (const double stiffness : {1e-2, 3.0, 5e5}) {
      const double c = viscous_damping(1.0, mass, stiffness);
      EXPECT_NEAR(c * c / (4.0 * mass * stiffness), 1.0, 1e-14);
      EXPECT_NEAR(viscous_damping(0.3, mass, stiffness) / c, 0.3, 1e-15);  // linear in ζ
    }
  }
  EXPECT_EQ(viscous_damping(0.0, 2.0, 3.0), 0.0);
  EXPECT_EQ(viscous_damping(0.5, 2.0, 0.0), 0.0);  // no spring, nothing to damp
}

TEST(NormalDamping, DashpotOpposesTheNormalMotion) {
  const double law_force = 10.0;
  const double damping = 4.0;
  // Approaching (v_n < 0): the dashpot adds to the repulsion; separating: it takes away.
  EXPECT_DOUBLE_EQ(damped_normal_force(law_force, damping, -0.5), 12.0);
  EXPECT_DOUBLE_EQ(damped_normal_force(law_force, damping, 0.5), 8.0);
  EXPECT_EQ(damped_normal_force(law_force, damping, 0.0), law_force);
  EXPECT_EQ(damped_normal_force(law_force, 0.0, 3.0), law_force);  // undamped: the law, unchanged
}

TEST(NormalDamping, NeverAttractive) {
  // Fast separation: F_law − c v_n < 0, but a contact cannot pull.
  EXPECT_EQ(damped_normal_force(1.0, 4.0, 10.0), 0.0);
  for (double speed = -2.0; speed <= 2.0; speed += 0.125) EXPECT_GE(damped_normal_force(3.0, 5.0, speed), 0.0);
}

}  // namespace
