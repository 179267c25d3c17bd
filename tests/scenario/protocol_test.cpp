// The quasi-static loading protocol: smooth plate ramps, the approach on the solid fraction, the
// servo hold, readings at equilibrium, and the errors when a target or an equilibrium cannot be
// reached.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "ellc/engine/servo.hpp"
#include "ellc/engine/simulation.hpp"
#include "ellc/scenario/protocol_stages.hpp"
#include "scenario_support.hpp"
#include "support/input_error.hpp"

namespace ellc::scenario {
namespace {

using testing::quick_scenario;
using testing::quick_scenario_text;
using testing::replace_line;

// The quick example (one constant ramped speed, an approach on the packing) with a servo hold.
std::string quasi_static_text() { return replace_line(quick_scenario_text(), "hold =", "hold = \"servo\""); }

TEST(LoadingProtocol, RampedPlateServoHoldAndAReadingAtEquilibrium) {
  ScenarioRunner runner(quick_scenario(quasi_static_text()), testing::in_memory(512));
  const double dt = runner.simulation().settings().dt;
  double previous = runner.simulation().walls()[engine::kTopWall].velocity;
  double largest_change = 0.0;
  bool approach_ended_on_packing = false;
  double largest_loop_gain = 0.0;  // of the hold's servo, g · speed · dt · k_A / P (engine/servo.hpp)
  while (!runner.done()) {
    const bool approaching = runner.state().approaching;
    runner.advance(1);
    if (runner.state().phase == Phase::hold) {
      const double stiffness_per_area = runner.simulation().wall_stiffness(engine::kTopWall) / (42.0 * 42.0);
      largest_loop_gain = std::max(largest_loop_gain, 5.0 * 0.05 * dt * stiffness_per_area / 200.0);
    }
    const double velocity = runner.simulation().walls()[engine::kTopWall].velocity;
    if (runner.state().phase != Phase::hold && runner.state().phase != Phase::done)
      largest_change = std::max(largest_change, std::abs(velocity - previous));
    previous = velocity;
    if (approaching && !runner.state().approaching) {
      const auto& sim = runner.simulation();
      const double solid = sim.particles().total_volume() / (42.0 * 42.0 * sim.gap());
      approach_ended_on_packing = solid >= 0.45 && solid < 0.46;
    }
  }
  // A half-cosine ramp over 10 µs changes the speed by at most (π/2)(Δv/T) dt per step.
  EXPECT_LT(largest_change, 1.6 * 0.05 * dt / 10.0 * 1.01);
  EXPECT_TRUE(approach_ended_on_packing);
  const RunSummary summary = runner.summary();
  EXPECT_NEAR(summary.held_pressure, 200.0, 1.0);  // the servo holds the target, no overshoot
  // The example's servo runs far below the stiffness cap, which therefore never acts on it.
  EXPECT_GT(largest_loop_gain, 0.0);
  EXPECT_LT(largest_loop_gain, engine::kServoStepFraction);
  EXPECT_LT(summary.loaded_unbalanced_force_ratio, 1e-3);
  EXPECT_LT(summary.loaded_plate_speed, 1e-3 * 0.05);
  EXPECT_GT(summary.springback_percent, 0.0);
}

// A servo gain 40 times the default puts the plain law's loop gain (g · speed · dt · Σk_n / (A P))
// above 2 on this packing: without the stiffness cap (engine/servo.hpp) the plate overshoots every
// step and the pressure cycles by tens of per cent about a mean below the target.
TEST(LoadingProtocol, AServoHoldFarAboveTheStableGainStillHoldsTheTargetWithoutACycle) {
  std::string text = replace_line(quasi_static_text(), "hold =", "hold = \"servo\"\nservo_gain = 200.0");
  ScenarioRunner runner(quick_scenario(text), testing::in_memory(512));
  std::vector<double> hold;
  while (!runner.done()) {
    runner.advance(1);
    if (runner.state().phase == Phase::hold) hold.push_back(runner.simulation().wall_pressure(engine::kTopWall));
  }
  ASSERT_GT(hold.size(), 200U);
  double largest_jump = 0.0;  // step to step, over the hold's last 200 steps
  for (std::size_t k = hold.size() - 200; k + 1 < hold.size(); ++k)
    largest_jump = std::max(largest_jump, std::abs(hold[k + 1] - hold[k]));
  EXPECT_LT(largest_jump, 0.01 * 200.0);
  EXPECT_NEAR(runner.summary().held_pressure, 200.0, 2.0);
}

TEST(LoadingProtocol, AnEquilibriumNotReachedInTimeStopsTheRunNamingTheCriterion) {
  std::string text =
      replace_line(quasi_static_text(), "hold_time", "hold_time = 1.0\nmax_hold_time = 1.0\nequilibrium_ratio = 1e-12");
  ScenarioRunner runner(quick_scenario(text), testing::in_memory(512));
  try {
    runner.advance(200'000);
    FAIL() << "the hold should not reach an unbalanced-force ratio of 1e-12 in 1 µs";
  } catch (const ProtocolError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("calendering.equilibrium_ratio"), std::string::npos) << message;
    EXPECT_NE(message.find("calendering.max_hold_time"), std::string::npos) << message;
  }
}

TEST(LoadingProtocol, BadProtocolInputNamesTheField) {
  const std::string base = quick_scenario_text();
  const auto message = [&](const std::string& starts, const std::string& line) {
    return ellc::test::input_error_message([&] { (void)quick_scenario(replace_line(base, starts, line)); });
  };
  EXPECT_NE(message("hold_time", "hold_time = 20.0\nequilibrium_ratio = 0").find("calendering.equilibrium_ratio"),
            std::string::npos);
  EXPECT_NE(message("ramp_time", "ramp_time = -1").find("calendering.ramp_time"), std::string::npos);
  EXPECT_NE(message("hold_time", "hold_time = 20.0\nmax_hold_time = 5").find("calendering.max_hold_time"),
            std::string::npos);
  EXPECT_NE(
      message("approach_solid_fraction", "approach_solid_fraction = 1.2").find("calendering.approach_solid_fraction"),
      std::string::npos);
  EXPECT_NE(message("target_pressure", "target_thickness = 20.0").find("calendering.hold"), std::string::npos);
}

}  // namespace
}  // namespace ellc::scenario
