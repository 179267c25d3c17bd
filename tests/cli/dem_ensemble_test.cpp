// `ellc dem --seeds N` end to end on examples/calendering_quick.toml: each member's directory holds
// what a single run with that seed writes, the ensemble summaries and plot are there, bad seeds
// exit 2 naming the option or field, and failed members exit 1 after the others have run.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "support/cli_run.hpp"
#include "support/read_text.hpp"

namespace {
namespace fs = std::filesystem;

using ellc::test::CliRun;
using ellc::test::run_cli;

using ellc::test::read_text;

std::string without_first_line(const std::string& text) { return text.substr(text.find('\n') + 1); }

class DemEnsembleCli : public ::testing::Test {
 protected:
  fs::path dir = fs::temp_directory_path() / ("ellc_dem_ensemble_" + std::to_string(::getpid()));
  void SetUp() override { fs::create_directories(dir); }
  void TearDown() override { fs::remove_all(dir); }

  // examples/calendering_quick.toml with its line starting `starts_with` replaced.
  std::string quick_variant(const std::string& name, const std::string& starts_with, const std::string& line) {
    std::string text = read_text(fs::path(ELLC_EXAMPLES_DIR) / "calendering_quick.toml");
    const auto at = text.find("\n" + starts_with);
    EXPECT_NE(at, std::string::npos) << starts_with;
    text.replace(at + 1, text.find('\n', at + 1) - at - 1, line);
    const fs::path file = dir / name;
    std::ofstream(file) << text;
    return file.string();
  }
  void expect_input_error(const std::string& arguments, const std::vector<std::string>& fragments) {
    const CliRun run = run_cli("dem " + arguments + " -q --no-plot -o " + (dir / "bad").string());
    EXPECT_EQ(run.exit_code, 2) << arguments << "\n" << run.output;
    for (const auto& fragment : fragments) EXPECT_NE(run.output.find(fragment), std::string::npos) << run.output;
    EXPECT_FALSE(fs::exists(dir / "bad" / "ensemble_summary.txt")) << arguments;
  }
};

TEST_F(DemEnsembleCli, TwoSeedsWriteWhatTwoSingleRunsWrite) {
  const std::string quick = (fs::path(ELLC_EXAMPLES_DIR) / "calendering_quick.toml").string();
  const fs::path out = dir / "ensemble";
  const CliRun run = run_cli("dem " + quick + " --seeds 2 --jobs 2 -q -o " + out.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  for (const char* name : {"ensemble_summary.txt", "ensemble_summary.csv", "pressure_thickness_ensemble.png"})
    EXPECT_TRUE(fs::exists(out / name)) << name;
  for (const char* member : {"seed_2026", "seed_2027"})
    for (const char* name : {"timeseries.csv", "summary.txt", "checkpoint.bin", "pressure_thickness.png"})
      EXPECT_TRUE(fs::exists(out / member / name)) << member << "/" << name;
  const std::string text = read_text(out / "ensemble_summary.txt");
  for (const char* line : {"members = 2\n", "finished = 2\n", "failed = 0\n", "seeds = 2026 2027\n",
                           "seed_2026 = finished\n", "seed_2027 = finished\n", "\nspringback_percent "})
    EXPECT_NE(text.find(line), std::string::npos) << line << "\n" << text;
  const std::string csv = read_text(out / "ensemble_summary.csv");
  EXPECT_EQ(csv.rfind("quantity,n,mean,sd,standard_error,min,max\n", 0), 0U) << csv;
  EXPECT_NE(csv.find("\nspringback_percent,2,"), std::string::npos) << csv;

  // The second member is the scenario with seed = 2027, run on its own.
  const std::string single_file = quick_variant("seed_2027.toml", "seed =", "seed = 2027");
  const CliRun single = run_cli("dem " + single_file + " -q --no-plot -o " + (dir / "single").string());
  ASSERT_EQ(single.exit_code, 0) << single.output;
  EXPECT_EQ(read_text(out / "seed_2027" / "timeseries.csv"), read_text(dir / "single" / "timeseries.csv"));
  EXPECT_EQ(without_first_line(read_text(out / "seed_2027" / "summary.txt")),  // the first names the file
            without_first_line(read_text(dir / "single" / "summary.txt")));
}

TEST_F(DemEnsembleCli, BadSeedsExitWithCode2) {
  const std::string quick = (fs::path(ELLC_EXAMPLES_DIR) / "calendering_quick.toml").string();
  expect_input_error(quick + " --seeds 0", {"--seeds = 0", "[1, 1000]"});
  expect_input_error(quick + " --seeds 1.5", {"--seeds = 1.5", "an integer"});
  expect_input_error(quick + " --seeds 1001", {"--seeds = 1001", "[1, 1000]"});
  expect_input_error(quick + " --seeds 2 --jobs 0", {"--jobs = 0", ">= 1"});
  expect_input_error(quick + " --jobs 2", {"--jobs = 2", "--seeds"});
  expect_input_error(quick + " --seeds 2 --restart x.bin", {"--restart = x.bin"});
  expect_input_error(quick + " --seeds 2 --jobs 2 --threads 2", {"--threads = 2", "--jobs 2"});
  expect_input_error(quick_variant("negative.toml", "seed =", "seeds = [1, -2]"), {"packing.seeds[1] = -2", ">= 0"});
  expect_input_error(quick_variant("float.toml", "seed =", "seeds = [1, 2.5]"), {"packing.seeds[1] = 2.5"});
  expect_input_error(quick_variant("twice.toml", "seed =", "seeds = [7, 7]"), {"packing.seeds = [7, 7]", "different"});
  expect_input_error(quick_variant("listed.toml", "seed =", "seeds = [7, 8]") + " --seeds 2",
                     {"--seeds = 2", "packing.seeds"});
}

// A time step 50 times the estimate (forced) sends a particle flying in every member within a few
// steps: each member is listed as failed with its message, and the exit code is 1.
TEST_F(DemEnsembleCli, FailedMembersGiveExitCode1) {
  const std::string runaway = quick_variant("runaway.toml", "safety", "safety = 0.2\ndt = 2.0");
  const fs::path out = dir / "runaway";
  const CliRun run = run_cli("dem " + runaway + " --seeds 2 --force -q -o " + out.string());
  EXPECT_EQ(run.exit_code, 1) << run.output;
  EXPECT_NE(run.output.find("2 of 2 ensemble members failed"), std::string::npos) << run.output;
  const std::string text = read_text(out / "ensemble_summary.txt");
  EXPECT_NE(text.find("failed = 2\n"), std::string::npos) << text;
  EXPECT_NE(text.find("seed_2026 = failed: particle"), std::string::npos) << text;
  EXPECT_NE(text.find("runaway"), std::string::npos) << text;
  EXPECT_TRUE(fs::exists(out / "seed_2027" / "checkpoint_failure.bin"));
  EXPECT_FALSE(fs::exists(out / "pressure_thickness_ensemble.png"));
}

}  // namespace
