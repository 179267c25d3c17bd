// The plate servo of both engines (engine/servo.hpp): its speed law in closed form, and its loop
// on a linear bed, where the law without the stiffness cap overshoots every step once the loop
// gain passes 2 and the capped one converges without crossing the target.

#include "ellc/engine/servo.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace ellc::engine {
namespace {

const PlateServo kHold{100.0, 100.0, 0.5, 5.0, 0.01};  // P = 100 MPa, 0.5 µm/µs, g = 5, 1 %

TEST(PlateServo, SpeedIsTheClampedProportionalLawWhenTheStiffnessCapDoesNotAct) {
  const double dt = 0.01;
  EXPECT_DOUBLE_EQ(servo_speed(kHold, 96.0, 1.0, dt), 0.5 * 5.0 * 0.04);    // presses below P
  EXPECT_DOUBLE_EQ(servo_speed(kHold, 104.0, 1.0, dt), -0.5 * 5.0 * 0.04);  // lifts above P
  EXPECT_DOUBLE_EQ(servo_speed(kHold, 10.0, 1.0, dt), 0.5);                 // full speed far from P
  EXPECT_DOUBLE_EQ(servo_speed(kHold, 100.9, 1.0, dt), 0.0);                // within the tolerance
  EXPECT_DOUBLE_EQ(servo_speed(kHold, 96.0, 0.0, dt), 0.5 * 5.0 * 0.04);    // no contacts: no cap
  const PlateServo release{2.0, 100.0, 0.5, 5.0, 0.05};                     // to p_r = 2 MPa, error over the held 100
  EXPECT_DOUBLE_EQ(servo_speed(release, 12.0, 1.0, dt), -0.5 * 5.0 * 0.1);
}

TEST(PlateServo, OneStepClosesAtMostHalfThePressureErrorAtTheContactsStiffness) {
  const double dt = 0.01;
  for (const double stiffness : {1e2, 1e3, 1e4, 1e5}) {  // MPa/µm
    for (const double pressure : {0.0, 50.0, 97.0, 103.0, 150.0, 400.0}) {
      const double speed = servo_speed(kHold, pressure, stiffness, dt);
      EXPECT_LE(std::abs(speed) * dt * stiffness, 0.5 * std::abs(100.0 - pressure) * (1.0 + 1e-12));
      EXPECT_GE(speed * (100.0 - pressure), 0.0);  // never away from the target
    }
  }
}

// A plate on a linear bed, p = k_A (z₀ − z): the loop gain of the uncapped law is
// g · rate · dt · k_A / P = 5 · 0.5 · 0.01 · 2·10⁴ / 100 = 5.
struct LinearBed {
  double stiffness = 2e4;  // k_A, MPa/µm
  double rest = 10.0;      // z₀
  [[nodiscard]] double pressure(double z) const { return std::max(0.0, stiffness * (rest - z)); }
};

// Final |p − P|/P after `steps` steps from p = 0.9 P, and whether p ever crossed P.
struct Loop {
  double final_error = 0.0;
  bool crossed = false;
};
Loop run_loop(bool with_cap, int steps) {
  const LinearBed bed;
  const double dt = 0.01;
  double z = bed.rest - 0.9 * kHold.target / bed.stiffness;
  Loop loop;
  for (int k = 0; k < steps; ++k) {
    const double p = bed.pressure(z);
    loop.crossed = loop.crossed || p > kHold.target * (1.0 + kHold.tolerance);
    z -= servo_speed(kHold, p, with_cap ? bed.stiffness : 0.0, dt) * dt;
  }
  loop.final_error = std::abs(bed.pressure(z) - kHold.target) / kHold.target;
  return loop;
}

TEST(PlateServo, TheCappedLoopConvergesWithoutOvershootWhereThePlainLawOscillates) {
  const Loop capped = run_loop(true, 50);
  EXPECT_LE(capped.final_error, kHold.tolerance);
  EXPECT_FALSE(capped.crossed);
  const Loop plain = run_loop(false, 50);  // what both engines did before the cap
  EXPECT_GT(plain.final_error, 0.2);
  EXPECT_TRUE(plain.crossed);
}

}  // namespace
}  // namespace ellc::engine
