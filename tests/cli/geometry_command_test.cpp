// `ellc geometry` at the edges of the number format (issue 19, item 1): a position ≥ 1e155, a
// huge semi-axis against a wall and max_overlap = 1e308 printed NaN/inf with exit code 0. Now
// every run prints finite numbers or exits with 2 naming the input field.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "support/cli_run.hpp"

namespace {
namespace fs = std::filesystem;

using ellc::test::CliRun;
using ellc::test::run_cli;

const std::string kMaterial = "[material]\nyoungs_modulus = 142000.0\npoisson_ratio = 0.25\nyield_stress = 7900.0\n";
const std::string kPair = kMaterial +
                          "[body_I]\nsemi_axes = [5.0, 3.0, 4.0]\nposition = [0.0, 0.0, 0.0]\n"
                          "[body_J]\nsemi_axes = [6.0, 2.5, 3.5]\nposition = [10.8, 0.0, 0.0]\n";
const std::string kWall = kMaterial +
                          "[body_I]\nsemi_axes = [5.0, 3.0, 4.0]\nposition = [0.0, 0.0, 3.9]\n"
                          "[wall]\npoint = [0.0, 0.0, 0.0]\nnormal = [0.0, 0.0, 1.0]\n";

class GeometryCli : public ::testing::Test {
 protected:
  fs::path dir = fs::temp_directory_path() / ("ellc_geometry_cli_" + std::to_string(::getpid()));
  void SetUp() override { fs::create_directories(dir); }
  void TearDown() override { fs::remove_all(dir); }
  CliRun run(const std::string& text) {
    const fs::path file = dir / "poses.toml";
    std::ofstream(file) << text;
    return run_cli("geometry " + file.string());
  }
  void expect_named(const std::string& text, const std::vector<std::string>& fragments) {
    const CliRun result = run(text);
    EXPECT_EQ(result.exit_code, 2) << result.output;
    for (const auto& fragment : fragments)
      EXPECT_NE(result.output.find(fragment), std::string::npos) << fragment << " not in " << result.output;
    EXPECT_EQ(result.output.find("nan"), std::string::npos) << result.output;
  }
};

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

TEST_F(GeometryCli, TheBaseCasesRunWithFiniteNumbers) {
  for (const std::string& text : {kPair, kWall}) {
    const CliRun result = run(text);
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_NE(result.output.find("force = "), std::string::npos) << result.output;
    EXPECT_EQ(result.output.find("nan"), std::string::npos) << result.output;
    EXPECT_EQ(result.output.find("inf"), std::string::npos) << result.output;
  }
}

TEST_F(GeometryCli, HugePositionIsRejectedByName) {
  expect_named(replaced(kPair, "position = [10.8, 0.0, 0.0]", "position = [2e155, 0.0, 0.0]"),
               {"body_J.position[0] = ", "within"});
  expect_named(replaced(kPair, "position = [0.0, 0.0, 0.0]", "position = [1e155, 1e155, 0.0]"),
               {"body_I.position[0] = "});
}

TEST_F(GeometryCli, HugeSemiAxisAgainstAWallIsRejectedByName) {
  expect_named(replaced(kWall, "semi_axes = [5.0, 3.0, 4.0]", "semi_axes = [5.0, 3.0, 1e200]"),
               {"body_I.semi_axes[2] = "});
  expect_named(replaced(kWall, "position = [0.0, 0.0, 3.9]", "position = [0.0, 0.0, 0.99e200]"),
               {"body_I.position[2] = "});
  expect_named(replaced(kWall, "point = [0.0, 0.0, 0.0]", "point = [0.0, 0.0, -1e300]"), {"wall.point[2] = "});
}

TEST_F(GeometryCli, HugeMaxOverlapIsRejectedByName) {
  expect_named("max_overlap = 1e308\n" + kPair, {"max_overlap = ", "at most 11 µm"});
  expect_named("max_overlap = 1e308\n" + kWall, {"max_overlap = ", "at most 10 µm"});
}

// A body wholly behind the wall: the overlap has no bound; refused naming the positions.
TEST_F(GeometryCli, BodyBehindTheWallIsRejectedByName) {
  expect_named(replaced(kWall, "position = [0.0, 0.0, 3.9]", "position = [0.0, 0.0, -1e40]"),
               {"body_I.position = [0, 0, -1e", "wall.point = [0, 0, 0]", "behind the wall"});
}

// Lengths at the top of their range and a stiff material: finite numbers or a named error.
TEST_F(GeometryCli, ExtremeButValidInputsGiveFiniteNumbersOrANamedError) {
  for (const char* modulus : {"1e300", "1e200", "142000.0"}) {
    std::string text = replaced(kPair, "youngs_modulus = 142000.0", std::string("youngs_modulus = ") + modulus);
    text = replaced(text, "yield_stress = 7900.0", "yield_stress = 1e280");
    text = replaced(text, "semi_axes = [5.0, 3.0, 4.0]", "semi_axes = [5e48, 3e48, 4e48]");
    text = replaced(text, "semi_axes = [6.0, 2.5, 3.5]\nposition = [10.8, 0.0, 0.0]",
                    "semi_axes = [6e48, 2.5e48, 3.5e48]\nposition = [10.8e48, 0.0, 0.0]");
    const CliRun result = run(text);
    if (result.exit_code == 0) {
      EXPECT_EQ(result.output.find("nan"), std::string::npos) << result.output;
      EXPECT_EQ(result.output.find("inf"), std::string::npos) << result.output;
    } else {  // the inputs first; the derived quantity that overflowed may follow
      EXPECT_EQ(result.exit_code, 2) << result.output;
      const auto named = result.output.find("youngs_modulus = ");
      EXPECT_NE(named, std::string::npos) << result.output;
      EXPECT_LT(named, result.output.find("delta_Y")) << result.output;
    }
  }
}

}  // namespace
