// The curve case reader (ellc/cases/case_file.hpp) at the edges of the number format (issue 19,
// item 1): lengths, overlaps and materials that would make the law overflow are rejected by the
// field the user wrote, never reported as a NaN of a derived quantity (`R_e = -nan`).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "ellc/cases/case_file.hpp"
#include "ellc/io/input_error.hpp"

namespace {

const std::string kCase = R"(
[material]
youngs_modulus = 142000.0
poisson_ratio = 0.25
yield_stress = 7900.0
[body_I]
semi_axes = [5.0, 4.0, 3.0]
[body_J]
aspect = [1.0, 1.25, 1.25]
mean_radius = 10.0
[protocol]
waypoints = [0.0, 2.0, 0.0]
)";

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

std::string rejection(const std::string& text) {
  try {
    (void)ellc::parse_curve_case(text, "case.toml");
  } catch (const ellc::InputError& error) {
    return error.what();
  }
  ADD_FAILURE() << "accepted:\n" << text;
  return {};
}

void expect_contains(const std::string& message, const std::string& fragment) {
  EXPECT_NE(message.find(fragment), std::string::npos) << "'" << fragment << "' not in: " << message;
  EXPECT_EQ(message.find("nan"), std::string::npos) << message;
  EXPECT_EQ(message.find("inf"), std::string::npos) << message;
}

TEST(CaseFile, TheGoodCaseReads) {
  const ellc::CurveCase curve_case = ellc::parse_curve_case(kCase, "case.toml");
  EXPECT_EQ(curve_case.waypoints.size(), 3u);
}

// Beyond a_I + a_J the centres have passed each other; 1e308 overflowed δ^{3/2} to inf.
TEST(CaseFile, WaypointBeyondTheBodiesIsRejectedByName) {
  expect_contains(rejection(replaced(kCase, "waypoints = [0.0, 2.0, 0.0]", "waypoints = [0.0, 1e308, 0.0]")),
                  "protocol.waypoints[1] = ");
  const std::string message = rejection(replaced(kCase, "waypoints = [0.0, 2.0, 0.0]", "waypoints = [0.0, 20.0]"));
  expect_contains(message, "protocol.waypoints[1] = 20");
  expect_contains(message, "a_I + a_J");
  // Relative waypoints are scaled first and checked the same way.
  expect_contains(rejection(replaced(kCase, "waypoints = [0.0, 2.0, 0.0]", "waypoints_relative = [0.0, 1e300]")),
                  "protocol.waypoints_relative[1] = ");
  // a_I + a_J exactly is the last admissible overlap.
  const double a_j = 10.0 / std::cbrt(1.25 * 1.25);
  EXPECT_NO_THROW((void)ellc::parse_curve_case(
      replaced(kCase, "waypoints = [0.0, 2.0, 0.0]", "waypoints = [0.0, " + std::to_string(4.9 + a_j) + "]"),
      "case.toml"));
}

TEST(CaseFile, LengthsOutsideTheNumberFormatAreRejectedByName) {
  expect_contains(rejection(replaced(kCase, "semi_axes = [5.0, 4.0, 3.0]", "semi_axes = [5.0, 4.0, 1e200]")),
                  "body_I.semi_axes[2] = ");
  expect_contains(rejection(replaced(kCase, "semi_axes = [5.0, 4.0, 3.0]", "semi_axes = [5.0, 1e-200, 3.0]")),
                  "body_I.semi_axes[1] = ");
  expect_contains(rejection(replaced(kCase, "mean_radius = 10.0", "mean_radius = 1e60")), "body_J.mean_radius = ");
  // Each ratio in range, but the semi-axes they give are not.
  expect_contains(rejection(replaced(kCase, "aspect = [1.0, 1.25, 1.25]\nmean_radius = 10.0",
                                     "aspect = [1.0, 1e45, 1e-45]\nmean_radius = 1e30")),
                  "body_J.aspect = [1, 1e");
}

TEST(CaseFile, TooManyPointsAreRejectedBeforeAllocating) {
  expect_contains(rejection(replaced(kCase, "waypoints = [0.0, 2.0, 0.0]",
                                     "waypoints = [0.0, 2.0, 0.0]\npoints_per_segment = 1000000000")),
                  "protocol.points_per_segment = ");
}

// δ_Y ~ (Y/E)² R_e underflows to 0 for Y/E = 1e-600: the message names the material fields
// before the derived quantity.
TEST(CaseFile, AnInvalidDerivedConstantNamesTheInputFields) {
  const std::string message = rejection(replaced(replaced(kCase, "youngs_modulus = 142000.0", "youngs_modulus = 1e300"),
                                                 "yield_stress = 7900.0", "yield_stress = 1e-300"));
  const auto material = message.find("[material] youngs_modulus = 1");
  const auto derived = message.find("delta_Y");
  EXPECT_NE(material, std::string::npos) << message;
  EXPECT_NE(derived, std::string::npos) << message;
  EXPECT_LT(material, derived) << message;
  EXPECT_NE(message.find("body_I.semi_axes = [5, 4, 3]"), std::string::npos) << message;
}

}  // namespace
