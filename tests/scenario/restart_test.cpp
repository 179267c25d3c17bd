// Restart from a checkpoint through the scenario runner: the restarted run reproduces the
// uninterrupted one bit for bit, and a checkpoint only restarts the scenario that wrote it.

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <unistd.h>

#include "ellc/io/input_error.hpp"
#include "scenario_support.hpp"
#include "support/simulation_state.hpp"

namespace ellc::scenario {
namespace {

using ellc::test::state_bytes;
using testing::in_memory;
using testing::quick_scenario;
using testing::quick_scenario_text;

// The plate compacting the loose deposit: ~1300 steps of the quick example.
constexpr std::uint64_t kSteps = 1300;

TEST(EngineDeterminism, RestartReproducesUninterruptedRunBitwise) {
  const Scenario scenario = quick_scenario(quick_scenario_text());
  ScenarioRunner whole(scenario, in_memory(512));
  whole.advance(kSteps);

  const std::string checkpoint =
      (std::filesystem::temp_directory_path() / ("ellc_restart_" + std::to_string(::getpid()) + ".bin")).string();
  {
    ScenarioRunner first(scenario, in_memory(512));
    first.advance(kSteps / 2);
    first.write_checkpoint(checkpoint);
  }
  RunOptions options = in_memory(512);
  options.restart_path = checkpoint;
  ScenarioRunner second(scenario, options);
  EXPECT_EQ(second.simulation().step_count(), kSteps / 2);
  second.advance(kSteps - kSteps / 2);
  std::remove(checkpoint.c_str());

  EXPECT_EQ(second.state().phase, whole.state().phase);
  EXPECT_EQ(second.state().load_start_gap, whole.state().load_start_gap);
  const std::string a = state_bytes(whole.simulation());
  const std::string b = state_bytes(second.simulation());
  ASSERT_EQ(a.size(), b.size());
  EXPECT_TRUE(a == b) << "restarted run differs from the uninterrupted one";
}

TEST(EngineDeterminism, RestartRefusesAnotherScenario) {
  const Scenario scenario = quick_scenario(quick_scenario_text());
  const std::string checkpoint =
      (std::filesystem::temp_directory_path() / ("ellc_other_" + std::to_string(::getpid()) + ".bin")).string();
  {
    ScenarioRunner first(scenario, in_memory(512));
    first.advance(10);
    first.write_checkpoint(checkpoint);
  }
  RunOptions options = in_memory();
  options.restart_path = checkpoint;
  const Scenario other = quick_scenario(testing::replace_line(quick_scenario_text(), "seed", "seed = 7"));
  EXPECT_THROW(ScenarioRunner(other, options), InputError);
  std::remove(checkpoint.c_str());
}

// The run's record (energy ledger, loaded state) travels in the checkpoint: a run restarted
// while settling under gravity with drag, the two terms the ledger integrates itself, reports
// the same energy balance bit for bit.
TEST(EngineDeterminism, RestartKeepsTheEnergyLedger) {
  std::string text = testing::replace_line(quick_scenario_text(), "insertion_fraction", "insertion_fraction = 0.25");
  text = testing::replace_line(text, "time = 0.0", "time = 30.0\ngravity = 0.02\ndrag_rate = 0.1");
  const Scenario scenario = quick_scenario(text);
  constexpr std::uint64_t kSettleSteps = 600;
  ScenarioRunner whole(scenario, in_memory(512));
  whole.advance(kSettleSteps);
  ASSERT_EQ(whole.state().phase, Phase::settle);

  const std::string checkpoint =
      (std::filesystem::temp_directory_path() / ("ellc_ledger_" + std::to_string(::getpid()) + ".bin")).string();
  {
    ScenarioRunner first(scenario, in_memory(512));
    first.advance(kSettleSteps / 2);
    first.write_checkpoint(checkpoint);
  }
  RunOptions options = in_memory(512);
  options.restart_path = checkpoint;
  ScenarioRunner second(scenario, options);
  EXPECT_TRUE(second.warnings().empty());
  second.advance(kSettleSteps - kSettleSteps / 2);
  const EnergyBalance a = whole.diagnostics().energy;
  const EnergyBalance b = second.diagnostics().energy;
  EXPECT_GT(a.gravity_work, 0.0);
  EXPECT_GT(a.drag_dissipation, 0.0);
  EXPECT_EQ(a.gravity_work, b.gravity_work);
  EXPECT_EQ(a.drag_dissipation, b.drag_dissipation);
  EXPECT_EQ(a.residual, b.residual);

  std::remove(checkpoint.c_str());
}

}  // namespace
}  // namespace ellc::scenario
