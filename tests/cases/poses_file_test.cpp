// The poses reader of `ellc geometry` (ellc/cases/poses_file.hpp): the examples read as their
// comments say, and bad input is rejected by an InputError naming the field.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "ellc/cases/poses_file.hpp"
#include "ellc/io/input_error.hpp"

namespace {

using ellc::PosesCase;

constexpr double kDegree = std::numbers::pi / 180.0;

std::string example(const char* name) { return std::string(ELLC_EXAMPLES_DIR) + "/" + name; }

const std::string kBodyJ = "[body_J]\nsemi_axes = [6.0, 2.5, 3.5]\nposition = [6.0, 5.5, 1.0]\n";
const std::string kPair = R"(
[material]
youngs_modulus = 142000.0
poisson_ratio = 0.25
yield_stress = 7900.0
[body_I]
semi_axes = [5.0, 3.0, 4.0]
)" + kBodyJ;

// The message of the InputError that parse_poses throws for `text` (fails the test if none).
std::string rejection(const std::string& text) {
  try {
    (void)ellc::parse_poses(text, "poses.toml");
  } catch (const ellc::InputError& error) {
    return error.what();
  }
  ADD_FAILURE() << "accepted:\n" << text;
  return {};
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

TEST(PosesFile, TipExamplePosesJTwistedAlongX) {
  const PosesCase poses = ellc::read_poses(example("poses_tip.toml"));
  ASSERT_TRUE(poses.body_j.has_value());
  EXPECT_FALSE(poses.wall.has_value());
  EXPECT_DOUBLE_EQ(poses.max_overlap, 0.0);
  // aspect [1, 1.25, 1.5] with mean radius 4.675: a = 4.675 / 1.875^(1/3).
  EXPECT_NEAR(poses.body_i.spec.semi_axes.x(), 4.675 / std::cbrt(1.875), 1e-12);
  EXPECT_TRUE(poses.body_i.pose.position.isZero());
  EXPECT_TRUE(poses.body_i.pose.orientation.isApprox(Eigen::Quaterniond::Identity()));
  EXPECT_NEAR(poses.body_j->pose.position.x(), 9.936190422698015, 1e-15);
  // No orientation given: the pose is the twist of 30° about the body's x axis alone.
  const Eigen::Quaterniond twist(Eigen::AngleAxisd(30.0 * kDegree, Eigen::Vector3d::UnitX()));
  EXPECT_NEAR(poses.body_j->spec.twist, 30.0 * kDegree, 1e-15);
  EXPECT_TRUE(poses.body_j->pose.orientation.isApprox(twist, 1e-14));
}

TEST(PosesFile, GeneralExampleNormalisesTheQuaternionAndTheAxis) {
  const PosesCase poses = ellc::read_poses(example("poses_general.toml"));
  ASSERT_TRUE(poses.body_j.has_value());
  EXPECT_EQ(poses.model.hertz, ellc::HertzMode::exact);
  EXPECT_TRUE(poses.body_i.spec.semi_axes.isApprox(Eigen::Vector3d(5.0, 3.0, 4.0)));
  const Eigen::Quaterniond about_z(Eigen::AngleAxisd(45.0 * kDegree, Eigen::Vector3d::UnitZ()));
  EXPECT_TRUE(poses.body_i.pose.orientation.isApprox(about_z, 1e-9));
  EXPECT_NEAR(poses.body_i.pose.orientation.norm(), 1.0, 1e-15);
  const Eigen::Quaterniond about_xy(Eigen::AngleAxisd(60.0 * kDegree, Eigen::Vector3d(1.0, 1.0, 0.0).normalized()));
  EXPECT_TRUE(poses.body_j->pose.orientation.isApprox(about_xy, 1e-14));
  EXPECT_TRUE(poses.body_j->pose.position.isApprox(Eigen::Vector3d(6.0, 5.5, 1.0)));
}

TEST(PosesFile, WallExampleHasAWallAndNoSecondBody) {
  const PosesCase poses = ellc::read_poses(example("poses_wall.toml"));
  EXPECT_FALSE(poses.body_j.has_value());
  ASSERT_TRUE(poses.wall.has_value());
  EXPECT_FALSE(poses.wall->material.has_value());  // the body's material
  EXPECT_TRUE(poses.wall->plane.point.isZero());
  EXPECT_TRUE(poses.wall->plane.normal.isApprox(Eigen::Vector3d::UnitZ()));
  EXPECT_NEAR(poses.body_i.pose.position.z(), 4.1, 1e-15);
}

TEST(PosesFile, WallNormalIsNormalisedAndWallMaterialRead) {
  const std::string text = replaced(kPair, kBodyJ,
                                    "[wall]\npoint = [0.0, 0.0, -1.0]\nnormal = [0.0, 0.0, 2.0]\n"
                                    "[wall.material]\nyoungs_modulus = 200000.0\npoisson_ratio = 0.3\n"
                                    "yield_stress = 1000.0\n");
  const PosesCase poses = ellc::parse_poses(text, "poses.toml");
  ASSERT_TRUE(poses.wall.has_value());
  EXPECT_TRUE(poses.wall->plane.normal.isApprox(Eigen::Vector3d::UnitZ()));
  ASSERT_TRUE(poses.wall->material.has_value());
  EXPECT_DOUBLE_EQ(poses.wall->material->youngs_modulus, 200000.0);
}

TEST(PosesFile, RejectsAnUnknownKeyNamingTheField) {
  const std::string message = rejection(replaced(kPair, "position =", "positon ="));
  EXPECT_EQ(message.rfind("poses.toml: unknown key 'body_J.positon'", 0), 0u) << message;
  const std::string wall = "[wall]\npoint = [0.0, 0.0, 0.0]\nnormal = [0.0, 0.0, 1.0]\nnormall = [0.0, 0.0, 1.0]\n";
  EXPECT_EQ(rejection(replaced(kPair, kBodyJ, wall)).rfind("poses.toml: unknown key 'wall.normall'", 0), 0u);
}

TEST(PosesFile, RejectsBothASecondBodyAndAWall) {
  const std::string text = kPair + "[wall]\npoint = [0.0, 0.0, 0.0]\nnormal = [0.0, 0.0, 1.0]\n";
  EXPECT_EQ(rejection(text), "poses.toml: the file gives both [body_J] and [wall]: expected one of the two");
}

TEST(PosesFile, RejectsBadPosesByName) {
  EXPECT_NE(rejection(replaced(kPair, "position = [6.0, 5.5, 1.0]", "position = [6.0, 5.5]")).find("body_J.position"),
            std::string::npos);
  EXPECT_NE(rejection(replaced(kPair, "position = [6.0, 5.5, 1.0]",
                               "orientation = [1.0, 0.0, 0.0, 0.0]\naxis = [0.0, 0.0, 1.0]\nangle_deg = 5.0"))
                .find("[body_J] gives both orientation and axis/angle_deg"),
            std::string::npos);
  EXPECT_NE(rejection(replaced(kPair, "position = [6.0, 5.5, 1.0]", "orientation = [0.0, 0.0, 0.0, 0.0]"))
                .find("body_J.orientation = a zero quaternion"),
            std::string::npos);
  EXPECT_NE(rejection(replaced(kPair, "position = [6.0, 5.5, 1.0]", "angle_deg = 5.0")).find("body_J.axis = missing"),
            std::string::npos);
  EXPECT_NE(rejection(replaced(kPair, "position = [6.0, 5.5, 1.0]", "axis = [0.0, 0.0, 0.0]\nangle_deg = 5.0"))
                .find("body_J.axis = [0, 0, 0]: expected a non-zero vector"),
            std::string::npos);
  EXPECT_NE(rejection("max_overlap = -0.5\n" + kPair).find("poses.toml: max_overlap = -0.5: expected"),
            std::string::npos);
}

TEST(PosesFile, RequiresASecondBodyOrAWall) {
  const std::string text = replaced(kPair, kBodyJ, "");
  EXPECT_NE(rejection(text).find("body_J = missing: expected a table [body_J] or a table [wall]"), std::string::npos);
}

}  // namespace

namespace {

// Issue 19, item 1: positions whose squared distance overflows (≥ 1e155 gave NaN), a semi-axis of
// 1e200 against a wall, and max_overlap = 1e308 are rejected by the field, with the bound.
TEST(PosesFile, RejectsValuesBeyondTheNumberFormatByName) {
  EXPECT_NE(rejection(replaced(kPair, "position = [6.0, 5.5, 1.0]", "position = [2e155, 5.5, 1.0]"))
                .find("body_J.position[0] = "),
            std::string::npos);
  EXPECT_NE(rejection(replaced(kPair, "semi_axes = [5.0, 3.0, 4.0]", "semi_axes = [5.0, 3.0, 1e200]"))
                .find("body_I.semi_axes[2] = "),
            std::string::npos);
  const std::string wall = "[wall]\npoint = [0.0, 0.0, -1e300]\nnormal = [0.0, 0.0, 1.0]\n";
  EXPECT_NE(rejection(replaced(kPair, kBodyJ, wall)).find("wall.point[2] = "), std::string::npos);
  const std::string message = rejection("max_overlap = 1e308\n" + kPair);
  EXPECT_NE(message.find("max_overlap = "), std::string::npos) << message;
  EXPECT_NE(message.find("at most 11 µm"), std::string::npos) << message;  // a_max^I + a_max^J = 5 + 6
  const std::string on_wall = rejection(
      "max_overlap = 10.5\n" + replaced(kPair, kBodyJ, "[wall]\npoint = [0.0, 0.0, 0.0]\nnormal = [0.0, 0.0, 1.0]\n"));
  EXPECT_NE(on_wall.find("at most 10 µm"), std::string::npos) << on_wall;  // 2 a_max^I
  EXPECT_NO_THROW((void)ellc::parse_poses("max_overlap = 11.0\n" + kPair, "poses.toml"));
}

}  // namespace
