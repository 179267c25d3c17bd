// The released state read at equilibrium (release = "servo"): the plate is unloaded by servo to a
// residual pressure and held there until the layer is at rest; the released thickness is the
// plate gap there.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "ellc/engine/simulation.hpp"
#include "ellc/scenario/diagnostics.hpp"
#include "ellc/scenario/protocol_stages.hpp"
#include "scenario_support.hpp"
#include "support/input_error.hpp"

namespace ellc::scenario {
namespace {

using testing::quick_scenario;
using testing::quick_scenario_text;
using testing::replace_line;

// The quick example with the release of its own file, at the given residual-pressure fraction.
std::string servo_release_text(double fraction) {
  return replace_line(replace_line(quick_scenario_text(), "release =", "release = \"servo\""),
                      "release_pressure_fraction", "release_pressure_fraction = " + std::to_string(fraction));
}

struct ReleaseRun {
  RunSummary summary;
  double top_pressure = 0.0;  // MPa, at the end
  double bottom_pressure = 0.0;
  double fastest_plate = 0.0;  // µm/µs, |v| of the plate during unload and relax
};

ReleaseRun run_to_the_end(const std::string& text) {
  ScenarioRunner runner(quick_scenario(text), testing::in_memory(512));
  ReleaseRun run;
  while (!runner.done()) {
    runner.advance(1);
    const Phase phase = runner.state().phase;
    if (phase == Phase::unload || phase == Phase::relax)
      run.fastest_plate = std::max(run.fastest_plate, std::abs(runner.simulation().walls()[engine::kTopWall].velocity));
  }
  run.summary = runner.summary();
  run.top_pressure = runner.simulation().wall_pressure(engine::kTopWall);
  run.bottom_pressure = runner.simulation().wall_pressure(engine::kBottomWall);
  return run;
}

TEST(ReleasedState, ServoUnloadsToTheResidualPressureAndReadsItAtEquilibrium) {
  const ReleaseRun run = run_to_the_end(servo_release_text(0.02));
  const RunSummary& s = run.summary;
  ASSERT_TRUE(s.finished);
  const double residual = 0.02 * s.held_pressure;
  EXPECT_NEAR(s.released_pressure, residual, 0.05 * residual);  // release_tolerance
  EXPECT_LT(s.released_unbalanced_force_ratio, 1e-3);
  EXPECT_LE(s.released_inertial_number, 1e-3);
  EXPECT_LE(s.loaded_inertial_number, 1e-3);
  EXPECT_LE(run.fastest_plate, 0.05 * (1.0 + 1e-12));  // never faster than lift_speed
  // At rest and without gravity, the floor carries what the plate pushes: the layer is in
  // static equilibrium, which a layer read as the plate leaves it is not.
  EXPECT_NEAR(run.bottom_pressure, run.top_pressure, 0.01 * run.top_pressure);
  // The released thickness is the plate gap at the reading, above the loaded one.
  EXPECT_GT(s.final_thickness, s.loaded_thickness);
  EXPECT_NEAR(s.springback_percent, 100.0 * (s.final_thickness - s.loaded_thickness) / s.loaded_thickness, 1e-9);
  for (const std::string& warning : summary_warnings(s))
    EXPECT_EQ(warning.find("state was read at"), std::string::npos) << warning;
}

// The unloading curve is monotonic: held at a larger residual pressure, the layer springs back less.
TEST(ReleasedState, ALargerResidualPressureLeavesLessSpringback) {
  const RunSummary low = run_to_the_end(servo_release_text(0.02)).summary;
  const RunSummary high = run_to_the_end(servo_release_text(0.2)).summary;
  ASSERT_TRUE(low.finished && high.finished);
  EXPECT_DOUBLE_EQ(low.loaded_thickness, high.loaded_thickness);  // the same run up to the release
  EXPECT_GT(high.final_thickness, high.loaded_thickness);
  EXPECT_LT(high.springback_percent, low.springback_percent);
}

TEST(ReleasedState, ARelaxationNotReachingEquilibriumNamesTheCriterion) {
  const std::string text = replace_line(replace_line(servo_release_text(0.02), "relax_time", "relax_time = 0.5"),
                                        "max_relax_time", "max_relax_time = 0.5");
  ScenarioRunner runner(quick_scenario(text), testing::in_memory(512));
  try {
    runner.advance(1'000'000);
    FAIL() << "the released layer should not be at rest 0.5 µs after reaching the residual pressure";
  } catch (const ProtocolError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("released state"), std::string::npos) << message;
    EXPECT_NE(message.find("calendering.max_relax_time"), std::string::npos) << message;
    EXPECT_NE(message.find("calendering.equilibrium_ratio"), std::string::npos) << message;
  }
}

TEST(ReleasedState, BadReleaseInputNamesTheField) {
  const std::string base = quick_scenario_text();
  const auto message = [&](const std::string& starts, const std::string& line) {
    return ellc::test::input_error_message([&] { (void)quick_scenario(replace_line(base, starts, line)); });
  };
  const std::string unknown = message("release =", "release = \"sudden\"");
  EXPECT_NE(unknown.find("calendering.release"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("sudden"), std::string::npos) << unknown;
  for (const char* value : {"0", "0.5", "-0.1"}) {
    const std::string text = message("release_pressure_fraction", std::string("release_pressure_fraction = ") + value);
    EXPECT_NE(text.find("calendering.release_pressure_fraction"), std::string::npos) << text;
  }
  const std::string tolerance = message("release =", "release = \"servo\"\nrelease_tolerance = 0");
  EXPECT_NE(tolerance.find("calendering.release_tolerance"), std::string::npos) << tolerance;
}

}  // namespace
}  // namespace ellc::scenario
