// Hostile scenarios (issue 19): each run either produces finite numbers or stops with an error
// that names the input field. The planned work is checked before anything is built
// (scenario/run_plan.hpp), and the messages blame what the user wrote.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "ellc/engine/simulation.hpp"
#include "ellc/io/input_error.hpp"
#include "ellc/scenario/run_plan.hpp"
#include "scenario_support.hpp"
#include "support/input_error.hpp"

namespace ellc::scenario {
namespace {

using ellc::test::input_error_message;
using testing::in_memory;
using testing::quick_scenario;
using testing::quick_scenario_text;
using testing::replace_line;

RunPlan plan_with(const std::string& starts_with, const std::string& line) {
  return plan_run(quick_scenario(replace_line(quick_scenario_text(), starts_with, line)));
}

bool mentions(const std::vector<std::string>& reasons, const std::string& text) {
  for (const auto& reason : reasons)
    if (reason.find(text) != std::string::npos) return true;
  return false;
}

// The plan of the quick example is within the limits, and its time step is the engine's estimate
// for the smallest semi-axis the spec can draw: never above the one the packing then gets.
TEST(RunPlan, QuickExampleIsWithinTheLimitsAndItsTimeStepIsConservative) {
  const Scenario scenario = quick_scenario(quick_scenario_text());
  const RunPlan plan = plan_run(scenario);
  EXPECT_TRUE(plan.impossible.empty());
  EXPECT_TRUE(plan.beyond_limits.empty()) << plan.beyond_limits.front();
  const ScenarioRunner runner(scenario, in_memory(512));
  const double dt = runner.simulation().settings().dt;
  EXPECT_LE(plan.time_step, dt);
  EXPECT_GT(plan.time_step, 0.5 * dt);
  EXPECT_GT(plan.steps, 1e3);
  EXPECT_LT(plan.steps, kMaxPlannedSteps);
  EXPECT_LT(plan.memory_bytes, 1e8);
}

// Runs that never end: each is refused before it starts, naming the field behind it.
TEST(RunPlan, RunsThatWouldNeverEndAreRefusedByField) {
  RunPlan plan = plan_with("hold_time", "hold_time = 1e308");
  EXPECT_TRUE(mentions(plan.impossible, "calendering.hold_time")) << plan.impossible.size();
  plan = plan_with("hold_time", "hold_time = 1e9");
  EXPECT_TRUE(plan.impossible.empty());
  EXPECT_TRUE(mentions(plan.beyond_limits, "calendering.hold_time"));
  plan = plan_with("time = 0.0", "time = 1e308");
  EXPECT_TRUE(mentions(plan.impossible, "settle.time"));
  plan = plan_with("hold_time", "hold_time = 20.0\nstart_gap = 1e9");
  EXPECT_TRUE(mentions(plan.impossible, "calendering.start_gap") ||
              mentions(plan.beyond_limits, "calendering.start_gap"));
  // E = 1e300: dt ~ 1e-149 µs.
  plan = plan_with("youngs_modulus", "youngs_modulus = 1e300");
  EXPECT_LT(plan.time_step, 1e-140);
  EXPECT_TRUE(mentions(plan.impossible, "material.youngs_modulus"));
  // An insertion fraction that puts the plate 490 m up.
  plan = plan_with("insertion_fraction", "insertion_fraction = 1e-9");
  EXPECT_GT(plan.layer_height, 1e8);
  EXPECT_FALSE(plan.impossible.empty() && plan.beyond_limits.empty());
  EXPECT_TRUE(mentions(plan.impossible, "packing.insertion_fraction") ||
              mentions(plan.beyond_limits, "packing.insertion_fraction"));
}

// The plan budgets each phase at the limit the protocol enforces (CalenderingSpec's
// hold_time_limit and relax_time_limit). Under the servo release the relaxation may last
// 5 × max(relax_time, hold_time); the plan once budgeted 5 × relax_time there.
TEST(RunPlan, BudgetsTheHoldAndTheServoReleaseAtTheProtocolsLimits) {
  const auto plan_with_hold = [](double hold_time) {
    std::string text = replace_line(quick_scenario_text(), "max_relax_time", "max_relax_time = 0.0");
    text = replace_line(text, "hold_time", "hold_time = " + std::to_string(hold_time));
    return plan_run(quick_scenario(text));
  };
  const Scenario scenario =
      quick_scenario(replace_line(quick_scenario_text(), "max_relax_time", "max_relax_time = 0.0"));
  ASSERT_TRUE(scenario.calendering.servo_release);
  const double relax_time = scenario.calendering.relax_time;
  const double hold_short = relax_time;  // both limits 5 × relax_time
  const double hold_long = 4.0 * relax_time;
  const double added = plan_with_hold(hold_long).simulated_time - plan_with_hold(hold_short).simulated_time;
  // The hold's limit grows by 5 Δ, and so does the servo release's relaxation limit.
  EXPECT_NEAR(added, 10.0 * (hold_long - hold_short), 1e-9 * added);
}

// mean_radius = 1e-4 µm in a 42 µm box once overflowed the cell grid's int and crashed: refused,
// even with --force, naming the fields.
TEST(RunPlan, CellGridBeyondItsIndexIsRefusedNotCrashed) {
  const RunPlan plan = plan_with("mean_radius", "mean_radius = 1e-4");
  ASSERT_FALSE(plan.impossible.empty());
  EXPECT_NE(plan.impossible.front().find("cell grid"), std::string::npos) << plan.impossible.front();
  EXPECT_NE(plan.impossible.front().find("packing.mean_radius"), std::string::npos);
  EXPECT_GT(plan.grid_cells, kMaxGridCells);
}

// lift_speed = 1e308 once gave a springback of inf %: the plate may not outrun the runaway limit.
// The number is printed in its short form.
TEST(HostileScenario, PlateFasterThanTheRunawayLimitIsRefusedByName) {
  const std::string message = input_error_message(
      [] { (void)quick_scenario(replace_line(quick_scenario_text(), "lift_speed", "lift_speed = 1e308")); });
  EXPECT_NE(message.find("calendering.lift_speed = 1e+308"), std::string::npos) << message;
  EXPECT_NE(message.find("time.max_speed"), std::string::npos) << message;
  EXPECT_EQ(message.find("000000000"), std::string::npos) << message;
  const std::string big = input_error_message(
      [] { (void)quick_scenario(replace_line(quick_scenario_text(), "mean_radius", "mean_radius = 1e200")); });
  EXPECT_NE(big.find("packing.mean_radius = 1e+200"), std::string::npos) << big;
}

TEST(HostileScenario, DirectoryGivenAsScenarioIsNamedAsSuch) {
  const std::string message =
      input_error_message([] { (void)read_scenario(std::filesystem::temp_directory_path().string()); });
  EXPECT_NE(message.find("is a directory"), std::string::npos) << message;
  EXPECT_EQ(message.find("missing table"), std::string::npos) << message;
  const std::string missing = input_error_message([] { (void)read_scenario("/nonexistent/scenario.toml"); });
  EXPECT_NE(missing.find("no such file"), std::string::npos) << missing;
}

// A plate that passes through the particles within a step is named as such, not blamed on the
// pressure target it could not reach.
TEST(HostileScenario, TunnellingPlateIsReportedAsSuch) {
  std::string text = replace_line(quick_scenario_text(), "approach_speed", "approach_speed = 0.0");
  text = replace_line(text, "speed = 0.05", "speed = 3000.0");
  text = replace_line(text, "ramp_time", "ramp_time = 0.0");
  text = replace_line(text, "mass_scaling", "mass_scaling = 10000.0\nmax_speed = 1e5");
  ScenarioRunner runner(quick_scenario(text), in_memory(512));
  std::string message;
  try {
    runner.advance(2000);
  } catch (const ProtocolError& error) {
    message = error.what();
  }
  EXPECT_NE(message.find("passed through"), std::string::npos) << message;
  EXPECT_NE(message.find("calendering.speed"), std::string::npos) << message;
}

// A particle that runs away by spinning is reported with its spin, not only its (small)
// translational speed.
TEST(HostileScenario, RunawaySpinIsReportedAsSpin) {
  engine::ParticleSet particles;
  particles.add(0, Eigen::Vector3d(1.0, 1.0, 1.0), 1e-3, Eigen::Vector3d(5.0, 5.0, 5.0),
                Eigen::Quaterniond::Identity());
  particles.angular_velocity[0] = Eigen::Vector3d(0.0, 0.0, 1e4);
  engine::EngineSettings settings;
  settings.contact.material = Material{142000.0, 0.25, 7900.0};
  settings.box = {20.0, 20.0};
  settings.dt = 1e-4;
  settings.max_speed = 50.0;
  std::array<engine::Wall, 2> walls{engine::Wall{0.0, 0.0, 1}, engine::Wall{20.0, 0.0, -1}};
  engine::Simulation simulation(settings, particles, walls);
  std::string message;
  try {
    simulation.step();
  } catch (const engine::RunawayError& error) {
    message = error.what();
  }
  EXPECT_NE(message.find("runaway spin"), std::string::npos) << message;
  EXPECT_NE(message.find("|omega| = 10000 rad/µs"), std::string::npos) << message;
  EXPECT_NE(message.find("max_speed = 50"), std::string::npos) << message;
}

}  // namespace
}  // namespace ellc::scenario
