// Bad scenario input: each error is an InputError that names the field.

#include <gtest/gtest.h>

#include <string>

#include "scenario_support.hpp"
#include "support/input_error.hpp"

namespace ellc::scenario {
namespace {

using engine::RunawayError;
using test::input_error_message;
using testing::in_memory;
using testing::quick_scenario;
using testing::quick_scenario_text;
using testing::replace_line;

TEST(EngineScenarioInput, QuickExampleIsValid) { EXPECT_NO_THROW(quick_scenario(quick_scenario_text())); }

TEST(EngineScenarioInput, UnknownKeyIsNamed) {
  const std::string text = replace_line(quick_scenario_text(), "seed", "seed = 1\ncolour = \"blue\"");
  const std::string message = input_error_message([&] { (void)quick_scenario(text); });
  EXPECT_NE(message.find("packing.colour"), std::string::npos) << message;
}

// `ellc dem --set`: overrides change the named entries before validation, are checked like the
// file (the error names the field and the --set), and are part of the text a checkpoint hashes.
TEST(EngineScenarioInput, OverridesReplaceEntriesAndAreValidatedLikeTheFile) {
  const std::string text = quick_scenario_text();
  const Scenario plain = parse_scenario(text, "calendering_quick.toml");
  const Scenario changed =
      parse_scenario(text, "calendering_quick.toml", {"calendering.speed=0.025", "packing.seed=2027"});
  EXPECT_EQ(changed.calendering.speed, 0.025);
  EXPECT_EQ(changed.calendering.lift_speed, plain.calendering.lift_speed);
  EXPECT_EQ(changed.calendering.approach_speed, plain.calendering.approach_speed);
  EXPECT_NE(changed.text, plain.text) << "a checkpoint of the changed run would restart the plain one";
  EXPECT_EQ(changed.source, "calendering_quick.toml --set calendering.speed=0.025 --set packing.seed=2027");

  const std::string bad =
      input_error_message([&] { (void)parse_scenario(text, "calendering_quick.toml", {"calendering.speed=-1"}); });
  EXPECT_NE(bad.find("calendering.speed"), std::string::npos) << bad;
  EXPECT_NE(bad.find("--set calendering.speed=-1"), std::string::npos) << bad;
  const std::string unknown =
      input_error_message([&] { (void)parse_scenario(text, "calendering_quick.toml", {"calendering.sped=0.1"}); });
  EXPECT_NE(unknown.find("calendering.sped"), std::string::npos) << unknown;
}

TEST(EngineScenarioInput, ParticleLargerThanBoxIsNamed) {
  const std::string text = replace_line(quick_scenario_text(), "size", "size = [30.0, 42.0]");
  const std::string message = input_error_message([&] { (void)quick_scenario(text); });
  EXPECT_NE(message.find("box.size"), std::string::npos) << message;
  EXPECT_NE(message.find("too large"), std::string::npos) << message;
}

TEST(EngineScenarioInput, OverlappingWallsAreNamed) {
  const std::string text = replace_line(quick_scenario_text(), "target_pressure", "target_thickness = 5.0");
  const std::string message = input_error_message([&] { (void)quick_scenario(text); });
  EXPECT_NE(message.find("calendering.target_thickness"), std::string::npos) << message;
  const std::string negative = replace_line(quick_scenario_text(), "target_pressure", "target_thickness = -1.0");
  EXPECT_NE(input_error_message([&] { (void)quick_scenario(negative); }).find("calendering.target_thickness"),
            std::string::npos);
}

TEST(EngineScenarioInput, BadValuesAreNamed) {
  const std::string text = replace_line(quick_scenario_text(), "friction", "friction = -0.3");
  EXPECT_NE(input_error_message([&] { (void)quick_scenario(text); }).find("contact.friction"), std::string::npos);
  const std::string shape = replace_line(quick_scenario_text(), "shape", "shape = \"cube\"");
  EXPECT_NE(input_error_message([&] { (void)quick_scenario(shape); }).find("packing.shape"), std::string::npos);
  for (const char* step : {"0.0", "0.5"}) {  // a Newton step length in (0, 0.1] rad
    const std::string newton = replace_line(quick_scenario_text(), "friction",
                                            std::string("friction = 0.3\nnarrow_phase_final_step = ") + step);
    EXPECT_NE(input_error_message([&] { (void)quick_scenario(newton); }).find("contact.narrow_phase_final_step"),
              std::string::npos)
        << step;
  }
}

// [settle] max_time: 0 means the default 3 × time, as documented; a positive value below time is
// refused with the field named.
TEST(EngineScenarioInput, SettleMaxTimeZeroIsTheDefault) {
  const std::string zero = replace_line(quick_scenario_text(), "time = 0.0", "time = 10.0\nmax_time = 0.0");
  EXPECT_EQ(quick_scenario(zero).settle.max_time, 30.0);
  const std::string short_max = replace_line(quick_scenario_text(), "time = 0.0", "time = 10.0\nmax_time = 5.0");
  EXPECT_NE(input_error_message([&] { (void)quick_scenario(short_max); }).find("settle.max_time"), std::string::npos);
}

TEST(EngineScenarioInput, TimeStepAboveEstimateNeedsForce) {
  const std::string text = replace_line(quick_scenario_text(), "safety", "safety = 0.2\ndt = 1.0");
  const Scenario scenario = quick_scenario(text);
  const std::string message = input_error_message([&] { ScenarioRunner runner(scenario, in_memory()); });
  EXPECT_NE(message.find("time.dt"), std::string::npos) << message;
  EXPECT_NE(message.find("--force"), std::string::npos) << message;
  RunOptions forced = in_memory();
  forced.force = true;
  ScenarioRunner runner(scenario, forced);
  ASSERT_FALSE(runner.warnings().empty());
  EXPECT_NE(runner.warnings().back().find("--force"), std::string::npos);
}

// A time step far above the estimate (forced) blows up: the run stops naming particle and step.
TEST(EngineScenarioInput, RunawayNamesParticleAndStep) {
  const std::string text = replace_line(quick_scenario_text(), "safety", "safety = 0.2\ndt = 2.0");
  RunOptions forced = in_memory();
  forced.force = true;
  ScenarioRunner runner(quick_scenario(text), forced);
  try {
    runner.advance(100'000);
    FAIL() << "no runaway detected";
  } catch (const RunawayError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("particle " + std::to_string(error.particle_id())), std::string::npos) << message;
    EXPECT_NE(message.find("step " + std::to_string(error.step())), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace ellc::scenario
