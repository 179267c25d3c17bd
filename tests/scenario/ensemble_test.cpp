// Ensembles over packing seeds (ensemble.hpp): the seed lists and their errors, the statistics of
// the members' summary lines, a failing member that does not stop the others, and results that
// do not depend on how many members run side by side (--jobs).

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <optional>
#include <sstream>
#include <string>

#include "ellc/scenario/ensemble.hpp"
#include "scenario_support.hpp"
#include "support/input_error.hpp"
#include "support/read_text.hpp"
#include "support/simulation_state.hpp"

namespace ellc::scenario {
namespace {

namespace fs = std::filesystem;
using test::input_error_message;
using test::state_bytes;
using testing::in_memory;
using testing::quick_scenario;
using testing::quick_scenario_text;
using testing::replace_line;

// The quick example with `seed = 2026` replaced by `line`.
std::string with_seed_line(const std::string& line) { return replace_line(quick_scenario_text(), "seed =", line); }

using ellc::test::read_text;

void expect_contains(const std::string& message, const std::vector<std::string>& fragments) {
  for (const auto& fragment : fragments) EXPECT_NE(message.find(fragment), std::string::npos) << message;
}

const FigureStatistics& figure(const EnsembleResult& result, const std::string& name) {
  for (const auto& f : result.statistics)
    if (f.name == name) return f;
  throw std::runtime_error("no figure " + name);
}

TEST(EnsembleSeeds, ConsecutiveSeedsStartAtThePackingSeed) {
  const Scenario scenario = quick_scenario(quick_scenario_text());
  EXPECT_TRUE(ensemble_seeds(scenario, std::nullopt).empty());  // a single run
  EXPECT_EQ(ensemble_seeds(scenario, 3), (std::vector<std::uint64_t>{2026, 2027, 2028}));
  EXPECT_EQ(ensemble_seeds(scenario, 1), (std::vector<std::uint64_t>{2026}));
  EXPECT_EQ(ensemble_seeds(scenario, 1000).size(), 1000U);
  EXPECT_EQ(member_directory("out/ens", 2027), (fs::path("out/ens") / "seed_2027").string());
}

TEST(EnsembleSeeds, TheFileListsItsSeeds) {
  const Scenario scenario = quick_scenario(with_seed_line("seeds = [5, 3, 0, 9]"));
  EXPECT_EQ(scenario.seeds, (std::vector<std::uint64_t>{5, 3, 0, 9}));
  EXPECT_EQ(ensemble_seeds(scenario, std::nullopt), scenario.seeds);
}

TEST(EnsembleInput, BadSeedListsAreNamed) {
  const auto message = [](const std::string& line) {
    return input_error_message([&] { (void)quick_scenario(with_seed_line(line)); });
  };
  expect_contains(message("seeds = [1, 2.5]"), {"packing.seeds[1] = 2.5", "an integer >= 0"});
  expect_contains(message("seeds = [1, 3.0]"), {"packing.seeds[1] = 3.0", "an integer >= 0"});
  expect_contains(message("seeds = [1, -3]"), {"packing.seeds[1] = -3", "an integer >= 0"});
  expect_contains(message("seeds = [\"a\"]"), {"packing.seeds[0] = \"a\"", "an integer >= 0"});
  expect_contains(message("seeds = 7"), {"packing.seeds = 7", "an array of integers"});
  expect_contains(message("seeds = []"), {"packing.seeds = a list of 0 seeds", "1 to 1000 different packing seeds"});
  std::string many = "seeds = [0";
  for (int k = 1; k <= 1000; ++k) many += ", " + std::to_string(k);
  expect_contains(message(many + "]"), {"packing.seeds = a list of 1001 seeds", "1 to 1000"});
  expect_contains(message("seeds = [4, 5, 4]"),
                  {"packing.seeds = [4, 5, 4]", "different", "4 is both packing.seeds[0] and packing.seeds[2]"});
  expect_contains(message("seed = 1\nseeds = [4, 5]"), {"packing.seeds = [4, 5]", "not both"});
}

TEST(EnsembleInput, SeedCountsOutOfRangeAreNamed) {
  const Scenario scenario = quick_scenario(quick_scenario_text());
  for (long long count : {0LL, -2LL, 1001LL, 1000000000000LL})
    expect_contains(input_error_message([&] { (void)ensemble_seeds(scenario, count); }),
                    {"--seeds = " + std::to_string(count), "in [1, 1000]"});
  const Scenario listed = quick_scenario(with_seed_line("seeds = [1, 2]"));
  expect_contains(input_error_message([&] { (void)ensemble_seeds(listed, 2); }),
                  {"--seeds = 2", "lists packing.seeds", "one of the two"});
  EnsembleOptions options;
  options.run = in_memory();
  options.run.restart_path = "x/checkpoint.bin";
  expect_contains(input_error_message([&] { (void)run_ensemble(scenario, {1, 2}, options); }), {"--restart"});
}

// Every numeric `key = value` line counts, also keys no one knows yet; flags, words and comments
// do not; a non-finite value is left out of its key's n.
TEST(EnsembleStatistics, EveryNumericSummaryLineIsAFigure) {
  const std::vector<std::string> texts = {
      "# ellc dem summary: a.toml\nfinished = true\nsteps = 10\nmax_pressure_MPa = 200.5\nmodel = hertz\n",
      "# x = 1\nfinished = true\nsteps = 14\nmax_pressure_MPa = 201.5\nnew_figure_um = +2.5e1\n",
      "finished = true\nsteps = 15\nmax_pressure_MPa = nan\n  new_figure_um   =  -1 \n",
  };
  const auto statistics = summary_statistics(texts);
  ASSERT_EQ(statistics.size(), 3U);
  EXPECT_EQ(statistics[0].name, "steps");
  EXPECT_EQ(statistics[1].name, "max_pressure_MPa");
  EXPECT_EQ(statistics[2].name, "new_figure_um");

  EXPECT_EQ(statistics[0].count, 3U);
  EXPECT_DOUBLE_EQ(statistics[0].mean, 13.0);
  EXPECT_DOUBLE_EQ(statistics[0].sd, std::sqrt((9.0 + 1.0 + 4.0) / 2.0));
  EXPECT_DOUBLE_EQ(statistics[0].standard_error, statistics[0].sd / std::sqrt(3.0));
  EXPECT_EQ(statistics[0].min, 10.0);
  EXPECT_EQ(statistics[0].max, 15.0);

  EXPECT_EQ(statistics[1].count, 2U);  // the nan is left out
  EXPECT_DOUBLE_EQ(statistics[1].mean, 201.0);
  EXPECT_DOUBLE_EQ(statistics[1].sd, std::sqrt(0.5));

  EXPECT_EQ(statistics[2].count, 2U);
  EXPECT_DOUBLE_EQ(statistics[2].mean, 12.0);
  EXPECT_EQ(statistics[2].min, -1.0);
  EXPECT_EQ(statistics[2].max, 25.0);

  const auto single = summary_statistics({"a = 3\n"});
  ASSERT_EQ(single.size(), 1U);
  EXPECT_EQ(single[0].count, 1U);
  EXPECT_EQ(single[0].mean, 3.0);
  EXPECT_TRUE(std::isnan(single[0].sd));  // undefined for one member
}

// Two members of the quick example, once one after the other (--jobs 1, the engine's default
// parallel_threshold: 100 particles run on one thread) and once side by side (--jobs 2, one engine
// thread each). That a threaded engine gives the same bits as one thread is
// EngineDeterminism.OneAndTwoThreadsGiveBitwiseEqualStates; here it would cost ~20 s of OpenMP
// barriers on a busy machine.
struct CapturedEnsemble {
  EnsembleResult result;
  std::map<std::uint64_t, std::string> final_states;
};

CapturedEnsemble run_captured(int jobs, std::size_t parallel_threshold) {
  CapturedEnsemble captured;
  EnsembleOptions options;
  options.run = in_memory(parallel_threshold);
  options.jobs = jobs;
  options.on_member_end = [&](const EnsembleMember& member, const ScenarioRunner* runner) {
    if (runner != nullptr) captured.final_states[member.seed] = state_bytes(runner->simulation());
  };
  const Scenario scenario = quick_scenario(quick_scenario_text());
  captured.result = run_ensemble(scenario, ensemble_seeds(scenario, 2), options);
  return captured;
}

class EnsembleOfTwo : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    one_job = run_captured(1, 512);
    two_jobs = run_captured(2, 512);
  }
  static inline std::optional<CapturedEnsemble> one_job;
  static inline std::optional<CapturedEnsemble> two_jobs;
};

TEST_F(EnsembleOfTwo, JobsDoNotChangeAnyBit) {
  for (const CapturedEnsemble* run : {&*one_job, &*two_jobs}) {
    ASSERT_EQ(run->result.members.size(), 2U);
    for (const auto& member : run->result.members) ASSERT_TRUE(member.finished) << member.error;
    ASSERT_EQ(run->final_states.size(), 2U);
  }
  for (std::uint64_t seed : {2026U, 2027U}) {
    const std::string& a = one_job->final_states.at(seed);
    const std::string& b = two_jobs->final_states.at(seed);
    ASSERT_EQ(a.size(), b.size());
    EXPECT_TRUE(a == b) << "seed " << seed << ": --jobs 2 differs from --jobs 1";
  }
  for (std::size_t i = 0; i < 2; ++i)
    EXPECT_EQ(one_job->result.members[i].summary_text, two_jobs->result.members[i].summary_text);
  // The two seeds are different packings.
  EXPECT_NE(one_job->final_states.at(2026), one_job->final_states.at(2027));
}

// The ensemble's figures against the members' own RunSummary, with mean and sd computed here:
// for two values, mean (x1 + x2) / 2 and sd |x1 - x2| / sqrt(2). summary.txt holds 8 significant
// digits (a rounding of up to 5e-8 of the value), hence the tolerance.
TEST_F(EnsembleOfTwo, StatisticsAreThoseOfTheMembersFigures) {
  const EnsembleResult& result = one_job->result;
  const RunSummary& a = result.members[0].summary;
  const RunSummary& b = result.members[1].summary;
  const std::map<std::string, std::pair<double, double>> expected = {
      {"steps", {double(a.steps), double(b.steps)}},
      {"dt_us", {a.dt, b.dt}},
      {"max_pressure_MPa", {a.max_pressure, b.max_pressure}},
      {"loaded_thickness_um", {a.loaded_thickness, b.loaded_thickness}},
      {"final_thickness_um", {a.final_thickness, b.final_thickness}},
      {"springback_percent", {a.springback_percent, b.springback_percent}},
      {"loaded_porosity", {a.loaded_porosity, b.loaded_porosity}},
      {"final_porosity", {a.final_porosity, b.final_porosity}},
      {"plastic_dissipation_pJ", {a.plastic_dissipation, b.plastic_dissipation}},
      {"particles", {double(a.particles), double(b.particles)}},
  };
  for (const auto& [name, values] : expected) {
    const auto [x1, x2] = values;
    const FigureStatistics& f = figure(result, name);
    const double tolerance = 1e-7 * std::max(std::abs(x1), std::abs(x2)) + 1e-300;
    EXPECT_EQ(f.count, 2U) << name;
    EXPECT_NEAR(f.mean, 0.5 * (x1 + x2), tolerance) << name;
    EXPECT_NEAR(f.sd, std::abs(x1 - x2) / std::sqrt(2.0), tolerance) << name;
    EXPECT_NEAR(f.standard_error, std::abs(x1 - x2) / 2.0, tolerance) << name;
    EXPECT_NEAR(f.min, std::min(x1, x2), tolerance) << name;
    EXPECT_NEAR(f.max, std::max(x1, x2), tolerance) << name;
  }
  EXPECT_GT(figure(result, "springback_percent").sd, 0.0);  // different packings, different layers
  EXPECT_EQ(figure(result, "particles").sd, 0.0);
  // Every numeric line of summary.txt is a figure (flags such as `finished` are not).
  std::size_t numeric_lines = 0;
  std::istringstream lines(result.members[0].summary_text);
  for (std::string line; std::getline(lines, line);)
    if (const auto equals = line.find(" = "); line[0] != '#' && equals != std::string::npos) {
      const std::string value = line.substr(equals + 3);
      char* end = nullptr;
      (void)std::strtod(value.c_str(), &end);
      if (end != value.c_str() && *end == '\0') ++numeric_lines;  // a number, not a flag or a name
    }
  EXPECT_EQ(result.statistics.size(), numeric_lines);
}

// A member whose time step is refused fails; the other runs to the end, the statistics are over
// it alone, and the files say which member failed and why.
TEST(Ensemble, AFailingMemberDoesNotStopTheOthers) {
  // Two seeds whose packings have different stable time steps; dt between the two estimates.
  std::vector<std::pair<double, std::uint64_t>> estimates;
  for (std::uint64_t seed = 2026; seed < 2036 && estimates.size() < 2; ++seed) {
    Scenario scenario = quick_scenario(quick_scenario_text());
    scenario.packing.seed = seed;
    const double estimate = ScenarioRunner(scenario, in_memory(512)).summary().dt_estimate;
    if (estimates.empty() || estimate != estimates[0].first) estimates.emplace_back(estimate, seed);
  }
  ASSERT_EQ(estimates.size(), 2U);
  std::sort(estimates.begin(), estimates.end());
  const double dt = 0.5 * (estimates[0].first + estimates[1].first);
  const std::uint64_t failing = estimates[0].second;
  const std::uint64_t running = estimates[1].second;
  char dt_line[64];
  std::snprintf(dt_line, sizeof dt_line, "safety = 0.2\ndt = %.17g", dt);
  const Scenario scenario = quick_scenario(replace_line(quick_scenario_text(), "safety", dt_line));

  const fs::path directory = fs::temp_directory_path() / ("ellc_ensemble_" + std::to_string(::getpid()));
  fs::remove_all(directory);
  EnsembleOptions options;
  options.run.output_directory = directory.string();
  options.jobs = 2;
  std::vector<std::uint64_t> ended;
  options.on_member_end = [&](const EnsembleMember& member, const ScenarioRunner*) { ended.push_back(member.seed); };
  const EnsembleResult result = run_ensemble(scenario, {failing, running}, options);

  EXPECT_EQ(ended.size(), 2U);
  ASSERT_EQ(result.members.size(), 2U);
  EXPECT_EQ(result.failed_count(), 1U);
  const EnsembleMember& failed = result.members[0];
  const EnsembleMember& finished = result.members[1];
  EXPECT_FALSE(failed.finished);
  expect_contains(failed.error, {"time.dt"});
  ASSERT_TRUE(finished.finished) << finished.error;
  const FigureStatistics& springback = figure(result, "springback_percent");
  EXPECT_EQ(springback.count, 1U);
  EXPECT_NEAR(springback.mean, finished.summary.springback_percent, 1e-7 * finished.summary.springback_percent);
  EXPECT_TRUE(std::isnan(springback.sd));

  // The finished member's directory holds what a single run writes; the summaries name the failure.
  const fs::path member = directory / ("seed_" + std::to_string(running));
  for (const char* name : {"timeseries.csv", "summary.txt", "checkpoint.bin"})
    EXPECT_TRUE(fs::exists(member / name)) << name;
  EXPECT_EQ(read_text(member / "summary.txt"), finished.summary_text);
  const std::string text = read_text(directory / "ensemble_summary.txt");
  expect_contains(text, {"members = 2", "finished = 1", "failed = 1", "seed_" + std::to_string(running) + " = finished",
                         "seed_" + std::to_string(failing) + " = failed: ", "time.dt", "springback_percent"});
  const std::string csv = read_text(directory / "ensemble_summary.csv");
  expect_contains(csv, {"quantity,n,mean,sd,standard_error,min,max\n", "\nspringback_percent,1,"});
  EXPECT_EQ(static_cast<std::size_t>(std::count(csv.begin(), csv.end(), '\n')), result.statistics.size() + 1);
  fs::remove_all(directory);
}

}  // namespace
}  // namespace ellc::scenario
