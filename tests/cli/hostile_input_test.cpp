// Hostile input through the CLI (issue 19): `ellc dem` checks the planned work before it builds
// anything (exit 2 naming the field; --force lifts the limits but not the impossible), a
// directory is named as such, and `ellc fit` refuses ambiguous, non-finite, degenerate and
// poorly fitted data, writes nothing then, and keeps the solvers' messages off the terminal.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
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

class HostileCli : public ::testing::Test {
 protected:
  fs::path dir = fs::temp_directory_path() / ("ellc_hostile_cli_" + std::to_string(::getpid()));
  void SetUp() override { fs::create_directories(dir); }
  void TearDown() override { fs::remove_all(dir); }

  // examples/calendering_quick.toml with its line starting `starts_with` replaced.
  std::string quick_variant(const std::string& starts_with, const std::string& line) {
    std::string text = read_text(fs::path(ELLC_EXAMPLES_DIR) / "calendering_quick.toml");
    const auto at = text.find("\n" + starts_with);
    EXPECT_NE(at, std::string::npos) << starts_with;
    text.replace(at + 1, text.find('\n', at + 1) - at - 1, line);
    const fs::path file = dir / "variant.toml";
    std::ofstream(file) << text;
    return file.string();
  }
  CliRun dem(const std::string& scenario, const std::string& extra = "") {
    return run_cli("dem " + scenario + " --no-plot -o " + (dir / "out").string() + " " + extra);
  }
  // Two 10 µm NMC spheres (the geometry of data/fea/g01_sphere.csv) and a CSV next to it.
  std::string fit_data(const std::string& csv_text) {
    std::ofstream(dir / "run.toml") << "[material]\nyoungs_modulus = 142000.0\npoisson_ratio = 0.25\n"
                                       "yield_stress = 7900.0\n[body_I]\nsemi_axes = [10.0, 10.0, 10.0]\n"
                                       "[body_J]\nsemi_axes = [10.0, 10.0, 10.0]\n";
    std::ofstream(dir / "run.csv") << csv_text;
    return (dir / "run.csv").string();
  }
};

TEST_F(HostileCli, PlannedWorkIsPrintedAndCheckedBeforeTheRun) {
  // Within the limits: the plan is printed (the run itself is cut short by --max-steps).
  CliRun run = dem((fs::path(ELLC_EXAMPLES_DIR) / "calendering_quick.toml").string(), "--max-steps 1");
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("ellc dem: plan: dt = "), std::string::npos) << run.output;

  // Beyond the limits: refused unless --force, before anything is written.
  fs::remove_all(dir / "out");
  run = dem(quick_variant("hold_time", "hold_time = 1e9"));
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("calendering.hold_time"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("run with --force"), std::string::npos) << run.output;
  EXPECT_FALSE(fs::exists(dir / "out" / "timeseries.csv"));

  // Never finishing: refused even with --force.
  for (const auto& [key, line, field] : std::vector<std::tuple<std::string, std::string, std::string>>{
           {"hold_time", "hold_time = 1e308", "calendering.hold_time"},
           {"time = 0.0", "time = 1e308", "settle.time"},
           {"youngs_modulus", "youngs_modulus = 1e300", "material.youngs_modulus"},
           {"insertion_fraction", "insertion_fraction = 1e-9", "packing.insertion_fraction"}}) {
    run = dem(quick_variant(key, line), "--force");
    EXPECT_EQ(run.exit_code, 2) << line << "\n" << run.output;
    EXPECT_NE(run.output.find(field), std::string::npos) << line << "\n" << run.output;
    EXPECT_NE(run.output.find("refused even with --force"), std::string::npos) << run.output;
  }
}

// mean_radius = 1e-4 in the quick example segfaulted (the cell grid's int count overflowed).
TEST_F(HostileCli, TinyParticlesInALargeBoxAreRefusedNotCrashed) {
  const CliRun run = dem(quick_variant("mean_radius", "mean_radius = 1e-4"), "--force");
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("cell grid"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("packing.mean_radius"), std::string::npos) << run.output;
}

TEST_F(HostileCli, DirectoryAsInputIsNamedAsADirectory) {
  for (const std::string command : {"dem", "curve", "geometry"}) {
    const CliRun run = run_cli(command + " " + dir.string() + (command == "dem" ? " --no-plot" : ""));
    EXPECT_EQ(run.exit_code, 2) << command << "\n" << run.output;
    EXPECT_NE(run.output.find("is a directory"), std::string::npos) << command << "\n" << run.output;
    EXPECT_EQ(run.output.find("missing table"), std::string::npos) << run.output;
  }
}

// Two `overlap` columns were read as the last one (RMS error 619 %, exit 0).
TEST_F(HostileCli, FitRefusesDuplicateColumnsNonFiniteAndDegenerateData) {
  CliRun run = run_cli("fit " + fit_data("overlap,force,overlap\n0.1,7314.556,0.2\n0.2,21044.248,0.4\n"));
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("columns 1 (\"overlap\") and 3 (\"overlap\") have the same name"), std::string::npos)
      << run.output;
  run = run_cli("fit " + fit_data("overlap,Force,force\n0.1,1,2\n"));
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("same name"), std::string::npos) << run.output;

  run = run_cli("fit " + fit_data("overlap,force\n0.1,7314.556\n0.2,nan\n"));
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("run.csv:3: force of data row 2 = \"nan\""), std::string::npos) << run.output;

  run = run_cli("fit " + fit_data("overlap,force\n0.5,100\n0.5,200\n0.5,300\n"));
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("all 3 data rows"), std::string::npos) << run.output;

  run = run_cli("fit " + fit_data("overlap,force\n0.1,7314.556\n1e308,21044.248\n"));
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("overlap of data row 2 = 1e+308"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("a_I + a_J = 20"), std::string::npos) << run.output;
  EXPECT_FALSE(fs::exists(dir / "model.toml"));
}

// Data the calibrated law cannot follow: the force of the FE sphere run, every other point
// tripled. The fit fails (exit 1) and writes nothing, unless --accept-poor-fit; either way the
// solvers' messages stay off the terminal.
TEST_F(HostileCli, PoorFitWritesNothingUnlessAccepted) {
  std::istringstream sphere(read_text(fs::path(ELLC_DATA_DIR) / "fea" / "g01_sphere.csv"));
  std::string line;
  std::getline(sphere, line);
  std::string csv = "overlap,force\n";
  for (int row = 0; std::getline(sphere, line); ++row) {
    const auto comma = line.find(',');
    const double force = std::stod(line.substr(comma + 1, line.find(',', comma + 1) - comma - 1));
    csv += line.substr(0, comma) + "," + std::to_string(row % 2 == 1 ? 3.0 * force : force) + "\n";
  }
  const std::string data = fit_data(csv);
  const fs::path model = dir / "model.toml";
  CliRun run = run_cli("fit " + data + " -o " + model.string());
  EXPECT_EQ(run.exit_code, 1) << run.output;
  EXPECT_NE(run.output.find("the calibrated law misses the data"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("nothing written"), std::string::npos) << run.output;
  EXPECT_FALSE(fs::exists(model));
  for (const char* solver_word : {"Ceres", "ceres", "WARNING", "iter ", "Termination"})
    EXPECT_EQ(run.output.find(solver_word), std::string::npos) << run.output;

  run = run_cli("fit " + data + " -o " + model.string() + " --accept-poor-fit");
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("written anyway (--accept-poor-fit)"), std::string::npos) << run.output;
  EXPECT_TRUE(fs::exists(model));
}

}  // namespace

namespace {
// `--set KEY=VALUE` before or after the scenario: applied (the plan changes), checked like the
// file (exit 2 naming the field and the --set), and refused when malformed.
TEST_F(HostileCli, SetOverridesAScenarioEntryAndIsChecked) {
  const std::string quick = (fs::path(ELLC_EXAMPLES_DIR) / "calendering_quick.toml").string();
  const CliRun plain = run_cli("dem " + quick + " --check");
  const CliRun halved = run_cli("dem --set calendering.speed=0.025 " + quick + " --set packing.seed=7 --check");
  ASSERT_EQ(halved.exit_code, 0) << halved.output;
  EXPECT_NE(halved.output.find("--set calendering.speed=0.025 --set packing.seed=7 is valid"), std::string::npos)
      << halved.output;
  EXPECT_NE(halved.output, plain.output) << "the slower plate should plan more steps";

  const CliRun bad = run_cli("dem " + quick + " --set calendering.speed=-1 --check");
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
  EXPECT_NE(bad.output.find("calendering.speed = -1: expected"), std::string::npos) << bad.output;
  const CliRun malformed = run_cli("dem " + quick + " --set calendering.speed --check");
  EXPECT_NE(malformed.exit_code, 0);
  EXPECT_NE(malformed.output.find("--set calendering.speed: expected KEY=VALUE"), std::string::npos)
      << malformed.output;
}
}  // namespace
