// `ellc curve` end to end: bad input exits 2 with a message naming the field; a good case writes
// every waypoint and reproduces the library's numbers.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "ellc/cases/case_file.hpp"

#include "support/cli_run.hpp"

namespace {
namespace fs = std::filesystem;

using ellc::test::CliRun;
using ellc::test::run_cli;

const char* kGoodCase = R"(
[material]
youngs_modulus = 142000.0
poisson_ratio = 0.25
yield_stress = 7900.0
[body_I]
aspect = [1.0, 1.0, 0.8]
mean_radius = 10.0
[body_J]
aspect = [1.0, 1.25, 1.25]
mean_radius = 10.0
[protocol]
waypoints = [0.0, 2.0, 0.0, 2.6, 0.0]
points_per_segment = 7
)";

class CurveCli : public ::testing::Test {
 protected:
  fs::path dir = fs::temp_directory_path() / ("ellc_cli_" + std::to_string(::getpid()));
  void SetUp() override { fs::create_directories(dir); }
  void TearDown() override { fs::remove_all(dir); }
  std::string write(const std::string& text) {
    const fs::path file = dir / "case.toml";
    std::ofstream(file) << text;
    return file.string();
  }
  // Replaces the first occurrence of `from` in the good case.
  std::string variant(const std::string& from, const std::string& to) {
    std::string text = kGoodCase;
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return write(text.replace(at, from.size(), to));
  }
  void expect_input_error(const std::string& case_path, const std::vector<std::string>& fragments) {
    const CliRun run = run_cli("curve " + case_path + " -o " + (dir / "out.csv").string());
    EXPECT_EQ(run.exit_code, 2) << run.output;
    for (const auto& fragment : fragments) EXPECT_NE(run.output.find(fragment), std::string::npos) << run.output;
    EXPECT_EQ(run.output.find("Segmentation"), std::string::npos);
  }
};

TEST_F(CurveCli, MissingTable) {
  std::string text = kGoodCase;
  text = text.substr(0, text.find("[protocol]"));
  expect_input_error(write(text), {"missing table [protocol]"});
}

TEST_F(CurveCli, NonPositiveSemiAxis) {
  expect_input_error(variant("aspect = [1.0, 1.0, 0.8]\nmean_radius = 10.0", "semi_axes = [5.0, -2.0, 3.0]"),
                     {"body_I.semi_axes[1] = -2", "> 0"});
}

TEST_F(CurveCli, PoissonRatioOutOfRange) {
  expect_input_error(variant("poisson_ratio = 0.25", "poisson_ratio = 0.7"),
                     {"material.poisson_ratio = 0.7", "(-1, 0.5)"});
}

TEST_F(CurveCli, NanAndInfinity) {
  expect_input_error(variant("youngs_modulus = 142000.0", "youngs_modulus = nan"),
                     {"material.youngs_modulus", "finite"});
  expect_input_error(variant("mean_radius = 10.0", "mean_radius = inf"), {"body_I.mean_radius", "finite"});
}

TEST_F(CurveCli, NegativeYieldStress) {
  expect_input_error(variant("yield_stress = 7900.0", "yield_stress = -5.0"), {"material.yield_stress = -5"});
}

TEST_F(CurveCli, UnknownKeyListsTheKnownOnes) {
  expect_input_error(variant("points_per_segment = 7", "points_per_segment = 7\nwaypionts = [1.0]"),
                     {"unknown key 'protocol.waypionts'", "known keys:", "points_per_segment"});
}

TEST_F(CurveCli, UnparsableToml) {
  expect_input_error(write("[material\nyoungs_modulus = 1"), {"not valid TOML", "line 1"});
}

TEST_F(CurveCli, WrongTypeNamesTheField) {
  expect_input_error(variant("points_per_segment = 7", "points_per_segment = \"many\""),
                     {"protocol.points_per_segment = \"many\"", "integer"});
}

TEST_F(CurveCli, MissingFileIsAnInputError) {
  const CliRun run = run_cli("curve " + (dir / "absent.toml").string());
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.output.find("no such file"), std::string::npos) << run.output;
}

TEST_F(CurveCli, AspectOutsideTheCalibratedRangeWarnsOnceAndRuns) {
  const CliRun run = run_cli("curve " + variant("aspect = [1.0, 1.0, 0.8]", "aspect = [1.0, 2.5, 0.8]") + " -o " +
                             (dir / "out.csv").string());
  EXPECT_EQ(run.exit_code, 0) << run.output;
  std::size_t count = 0;
  for (std::size_t at = run.output.find("warning"); at != std::string::npos; at = run.output.find("warning", at + 1))
    ++count;
  EXPECT_EQ(count, 1u) << run.output;
  EXPECT_NE(run.output.find("calibrated range"), std::string::npos);
}

TEST_F(CurveCli, CsvVisitsEveryWaypointAndMatchesTheLibrary) {
  const std::string csv = (dir / "out.csv").string();
  const CliRun run = run_cli("curve " + write(kGoodCase) + " -o " + csv);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  for (const char* item : {"R_e", "f1, f2", "delta_Y", "F_pY", "lambda_max", "epsilon_max", "delta_max", "delta_p"})
    EXPECT_NE(run.output.find(item), std::string::npos) << item;
  std::ifstream in(csv);
  std::string header, line;
  std::getline(in, header);
  EXPECT_EQ(header.rfind("overlap,force,regime", 0), 0u) << header;
  std::vector<double> overlaps;
  std::vector<std::string> regimes;
  while (std::getline(in, line)) {
    std::stringstream row(line);
    std::string overlap, force, regime;
    std::getline(row, overlap, ',');
    std::getline(row, force, ',');
    std::getline(row, regime, ',');
    overlaps.push_back(std::stod(overlap));
    regimes.push_back(regime);
  }
  ASSERT_EQ(overlaps.size(), 1u + 4u * 7u);
  for (int waypoint = 0; waypoint < 5; ++waypoint)
    EXPECT_EQ(overlaps[waypoint * 7], (std::vector<double>{0.0, 2.0, 0.0, 2.6, 0.0})[waypoint]);
  EXPECT_EQ(regimes[0], "separated");
  EXPECT_EQ(regimes[7], "elastic_plastic");
  EXPECT_EQ(regimes[8], "unloading");
  EXPECT_EQ(regimes.back(), "separated");
}

TEST_F(CurveCli, ShippedPaperCasesRun) {
  for (const char* name : {"paper_case1.toml", "paper_case2.toml"}) {
    const CliRun run =
        run_cli(std::string("curve ") + ELLC_EXAMPLES_DIR + "/" + name + " -o " + (dir / "p.csv").string());
    EXPECT_EQ(run.exit_code, 0) << run.output;
    EXPECT_EQ(run.output.find("warning"), std::string::npos) << run.output;
  }
}
// Issue 19, item 1: a run either writes finite numbers or stops with exit code 2 naming the input
// field. A waypoint near 1e308 printed NaN forces with exit code 0.
TEST_F(CurveCli, HugeWaypointIsRejectedByName) {
  expect_input_error(variant("waypoints = [0.0, 2.0, 0.0, 2.6, 0.0]", "waypoints = [0.0, 1.7e308, 0.0]"),
                     {"protocol.waypoints[1] = ", "a_I + a_J"});
  EXPECT_FALSE(fs::exists(dir / "out.csv"));
}

// A material whose derived yield overlap underflows (Y/E = 1e-600) names the material fields.
TEST_F(CurveCli, InvalidDerivedConstantNamesTheMaterial) {
  std::string text = kGoodCase;
  text.replace(text.find("youngs_modulus = 142000.0"), 25, "youngs_modulus = 1e300");
  text.replace(text.find("yield_stress = 7900.0"), 21, "yield_stress = 1e-300");
  const CliRun run = run_cli("curve " + write(text) + " -o " + (dir / "out.csv").string());
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("[material] youngs_modulus = 1"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("nan"), std::string::npos) << run.output;
}

// Every length at the top of its range and a stiff material: whatever the law gives is either
// written finite or refused naming the inputs; never a NaN or inf in the CSV, never exit code 0
// with one.
TEST_F(CurveCli, ExtremeButValidInputsGiveFiniteNumbersOrANamedError) {
  for (const char* modulus : {"1e300", "1e250", "142000.0"}) {
    std::string text = kGoodCase;
    text.replace(text.find("youngs_modulus = 142000.0"), 25, std::string("youngs_modulus = ") + modulus);
    text.replace(text.find("yield_stress = 7900.0"), 21, "yield_stress = 1e280");
    text.replace(text.find("mean_radius = 10.0"), 18, "mean_radius = 1e49");
    text.replace(text.find("waypoints = [0.0, 2.0, 0.0, 2.6, 0.0]"), 37, "waypoints = [0.0, 1e48, 0.0]");
    const fs::path csv = dir / "out.csv";
    fs::remove(csv);
    const CliRun run = run_cli("curve " + write(text) + " -o " + csv.string());
    if (run.exit_code == 0) {
      std::ifstream in(csv);
      const std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      EXPECT_EQ(content.find("nan"), std::string::npos) << modulus;
      EXPECT_EQ(content.find("inf"), std::string::npos) << modulus;
    } else {
      EXPECT_EQ(run.exit_code, 2) << run.output;
      EXPECT_NE(run.output.find("youngs_modulus = "), std::string::npos) << run.output;
      EXPECT_FALSE(fs::exists(csv)) << modulus;
    }
  }
}

}  // namespace
