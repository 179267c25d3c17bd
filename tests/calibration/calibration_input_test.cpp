// Reading calibration data: CSV columns, the case file next to it, and the error messages.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "ellc/calibration/calibration_case.hpp"
#include "support/input_error.hpp"
#include "support/nmc.hpp"

namespace ellc {
namespace {

namespace fs = std::filesystem;

const std::string kCaseToml = test::nmc_material_toml() + R"([body_I]
aspect = [1.0, 1.0, 0.8]
mean_radius = 10.0
[body_J]
aspect = [1.0, 1.25, 1.25]
mean_radius = 10.0
[protocol]
waypoints_relative = [0.0, 0.1]
)";

class CalibrationInput : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ = fs::temp_directory_path() / ("ellc_calibration_input_" + std::to_string(::getpid()) + "_" +
                                           ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(folder_);
  }
  void TearDown() override { fs::remove_all(folder_); }
  std::string write(const std::string& name, const std::string& text) {
    const fs::path path = folder_ / name;
    std::ofstream(path) << text;
    return path.string();
  }
  static std::string message_of(const std::string& argument) {
    return test::input_error_message([&] { (void)read_calibration_case(argument); });
  }
  fs::path folder_;
};

TEST_F(CalibrationInput, SidecarTomlAndExtraColumns) {
  write("run.toml", kCaseToml);
  const std::string csv = write("run.incomplete.csv", "overlap,force,segment\n0.1,7000,1\n0.2,21000,1\n");
  const CalibrationCase data = read_calibration_case(csv);
  EXPECT_EQ(data.name, "run");
  ASSERT_EQ(data.forces.size(), 2u);
  EXPECT_DOUBLE_EQ(data.forces[1], 21000.0);
  EXPECT_NEAR(data.body_i.semi_axes.z() / data.body_i.semi_axes.x(), 0.8, 1e-12);
}

TEST_F(CalibrationInput, ExplicitPairingAndCommentLine) {
  const std::string toml = write("geometry.toml", kCaseToml);
  const std::string csv = write("a.csv", "# from somewhere\nforce,overlap\n7000,0.1\n21000,0.2\n");
  const CalibrationCase explicit_case = read_calibration_case(csv + ":" + toml);
  EXPECT_DOUBLE_EQ(explicit_case.overlaps[0], 0.1);
  const std::string commented = write("b.csv", "# case = geometry.toml\noverlap,force\n0.1,7000\n0.2,21000\n");
  EXPECT_EQ(read_calibration_case(commented).name, "b");
}

TEST_F(CalibrationInput, ErrorsNameTheFileLineAndField) {
  write("bad.toml", kCaseToml);
  EXPECT_NE(
      message_of(write("bad.csv", "overlap,force\n0.1,7000\n0.2,x\n")).find("bad.csv:3: force of data row 2 = \"x\""),
      std::string::npos);
  EXPECT_NE(message_of(write("nohead.csv", "delta,F\n0.1,1\n")).find("overlap and force"), std::string::npos);
  EXPECT_NE(message_of(write("alone.csv", "overlap,force\n0.1,1\n")).find("alone.toml"), std::string::npos);
  write("short.toml", kCaseToml);
  EXPECT_NE(message_of(write("short.csv", "overlap,force\n0.1\n")).find("short.csv:2"), std::string::npos);
  write("typo.toml", std::string(kCaseToml) + "[bodyJ]\n");
  EXPECT_NE(message_of(write("typo.csv", "overlap,force\n0.1,1\n")).find("bodyJ"), std::string::npos);
}

}  // namespace
}  // namespace ellc
