// Results independent of the thread count, and restart equivalence, both bit for bit.

#include <gtest/gtest.h>
#include <omp.h>

#include <cstdio>
#include <filesystem>

#include <unistd.h>

#include "ellc/io/input_error.hpp"

#include "engine_support.hpp"

namespace ellc::engine {
namespace {

using testing::in_memory;
using testing::quick_scenario;
using testing::quick_scenario_text;
using testing::state_bytes;

// Settling (particles raining onto the floor) into the first part of the load: ~1300 steps.
constexpr std::uint64_t kSteps = 1300;

// A denser, shorter variant for the thread test (every loop threaded, even for 100 particles):
// insertion at 40 % solid, 10 µs of settling, then ~300 steps of loading.
constexpr std::uint64_t kThreadSteps = 600;
std::string thread_test_scenario() {
  std::string text = quick_scenario_text();
  text = testing::replace_line(text, "insertion_fraction", "insertion_fraction = 0.4");
  text = testing::replace_line(text, "time = 40.0", "time = 10.0");
  return text;
}

std::string run_with_threads(int threads) {
  const int previous = omp_get_max_threads();
  omp_set_num_threads(threads);
  ScenarioRunner runner(quick_scenario(thread_test_scenario()), in_memory(0));
  runner.advance(kThreadSteps);
  omp_set_num_threads(previous);
  EXPECT_EQ(runner.state().phase, Phase::load);
  EXPECT_GT(runner.simulation().contact_counts().particle_contacts, 20U);
  return state_bytes(runner.simulation());
}

TEST(EngineDeterminism, OneAndTwoThreadsGiveBitwiseEqualStates) {
  const std::string one = run_with_threads(1);
  const std::string two = run_with_threads(2);
  ASSERT_EQ(one.size(), two.size());
  EXPECT_TRUE(one == two) << "the state after " << kThreadSteps << " steps depends on the thread count";
}

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

}  // namespace
}  // namespace ellc::engine
