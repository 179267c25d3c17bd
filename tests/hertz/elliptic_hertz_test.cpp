// Elliptical Hertz: sphere limit, the exact mode against Johnson's relations (evaluated with the
// standard library's elliptic integrals), Hale versus exact, and eq. (5) against the tensor sum.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstring>

#include "ellc/hertz/elliptic_hertz.hpp"
#include "support/nmc.hpp"

namespace {
using ellc::HertzMode;

using ellc::test::kNmc;

// E_e of two NMC bodies, E / (2 (1 − ν²)).
constexpr double kModulus = kNmc.youngs_modulus / (2.0 * (1.0 - kNmc.poisson_ratio * kNmc.poisson_ratio));

TEST(Hertz, TwoEqualSpheresGiveHalfTheRadiusAndNoCorrection) {
  const ellc::PrincipalCurvatures sphere{0.1, 0.1};  // R = 10
  for (HertzMode mode : {HertzMode::hale, HertzMode::exact}) {
    const auto shape = ellc::hertz_shape(ellc::relative_curvature(sphere, sphere, 0.3), mode);
    EXPECT_NEAR(shape.equivalent_radius, 5.0, 1e-14);
    EXPECT_NEAR(shape.f1, 1.0, 1e-14);
    EXPECT_NEAR(shape.f2, 1.0, 1e-14);
    EXPECT_NEAR(shape.eccentricity_sq, 0.0, 1e-14);
    // Classical sphere Hertz: F = 4/3 E* sqrt(R*) δ^{3/2}, a = sqrt(R* δ), p0 = 2 E* a / (π R*).
    const auto contact = ellc::hertz_contact(shape, kModulus, 0.2);
    EXPECT_NEAR(contact.force, 4.0 / 3.0 * kModulus * std::sqrt(5.0) * std::pow(0.2, 1.5), 1e-9);
    EXPECT_NEAR(contact.semi_axis_major, 1.0, 1e-14);
    EXPECT_NEAR(contact.peak_pressure, 2.0 * kModulus / (M_PI * 5.0), 1e-9);
  }
}

// Johnson (1985) Sec. 4.2 with e² = 1 − (b/a)², K, E of modulus e.
struct JohnsonResiduals {
  double ratio, overlap, a_sum, force;
};
JohnsonResiduals johnson_residuals(double a_sum, double b_sum, double overlap, const ellc::HertzContact& c) {
  const double k = c.semi_axis_minor / c.semi_axis_major;
  const double e = std::sqrt(1.0 - k * k);
  const double big_k = std::comp_ellint_1(e);
  const double big_e = std::comp_ellint_2(e);
  const double a = c.semi_axis_major, b = c.semi_axis_minor, p0 = c.peak_pressure;
  return {((big_e / (k * k) - big_k) / (big_k - big_e)) / (b_sum / a_sum) - 1.0,
          (p0 * b * big_k / kModulus) / overlap - 1.0,
          (p0 * b * (big_k - big_e) / (kModulus * a * a * e * e)) / a_sum - 1.0,
          (2.0 / 3.0 * M_PI * a * b * p0) / c.force - 1.0};
}

TEST(Hertz, ExactModeSatisfiesJohnsonsRelations) {
  const double a_sum = 0.05;
  for (double ratio : {1.2, 2.0, 3.0, 5.0, 10.0, 30.0, 100.0}) {
    const ellc::RelativeCurvature curvature{a_sum, ratio * a_sum};
    const auto shape = ellc::hertz_shape(curvature, HertzMode::exact);
    for (double overlap : {1e-3, 0.1, 1.0}) {
      const auto contact = ellc::hertz_contact(shape, kModulus, overlap);
      const auto r = johnson_residuals(curvature.a_sum, curvature.b_sum, overlap, contact);
      EXPECT_LT(std::abs(r.ratio), 1e-9) << "B/A " << ratio;
      EXPECT_LT(std::abs(r.overlap), 1e-9) << "B/A " << ratio;
      EXPECT_LT(std::abs(r.a_sum), 1e-9) << "B/A " << ratio;
      EXPECT_LT(std::abs(r.force), 1e-12) << "B/A " << ratio;
    }
  }
}

TEST(Hertz, ExactModeIsContinuousIntoTheCircularLimit) {
  // Cancellation-free integrals: a hair of ellipticity must still give f1, f2 → 1 smoothly.
  const auto near_round = ellc::hertz_shape({0.05, 0.05 * (1.0 + 1e-9)}, HertzMode::exact);
  EXPECT_NEAR(near_round.f1, 1.0, 1e-8);
  EXPECT_NEAR(near_round.f2, 1.0, 1e-8);
  EXPECT_LT(near_round.eccentricity_sq, 1e-8);
}

TEST(Hertz, HaleAgreesWithExactWithinOnePointFivePercentInForce) {
  for (double ratio = 1.0; ratio <= 100.0; ratio *= 1.1) {
    const ellc::RelativeCurvature curvature{0.05, 0.05 * ratio};
    const double hale = ellc::hertz_contact(ellc::hertz_shape(curvature, HertzMode::hale), kModulus, 0.3).force;
    const double exact = ellc::hertz_contact(ellc::hertz_shape(curvature, HertzMode::exact), kModulus, 0.3).force;
    EXPECT_LT(std::abs(hale / exact - 1.0), 0.015) << "B/A = " << ratio;
  }
}

TEST(Hertz, HaleFactorsFallSlowlyFromOne) {
  double previous_f1 = 1.0, previous_f2 = 1.0;
  for (double ratio = 1.0; ratio <= 100.0; ratio *= 1.5) {
    const auto shape = ellc::hertz_shape({1.0, ratio}, HertzMode::hale);
    EXPECT_LE(shape.f1, previous_f1);
    EXPECT_LE(shape.f2, previous_f2);
    EXPECT_GT(shape.f1, 0.8);
    previous_f1 = shape.f1;
    previous_f2 = shape.f2;
  }
}

// Eq. (4), (7) evaluated directly in long double (pow, expm1): the double evaluation, which takes
// log(expm1(pL)) from a series below B/A ≈ 1500 to save transcendental calls, must agree to
// rounding on both sides of that switch.
TEST(Hertz, HaleFactorsAreEquationFourToRounding) {
  for (double ratio = 1.0; ratio < 1e5; ratio *= 1.0 + 1.0 / 64.0) {
    for (const double r : {ratio, std::nextafter(ratio, 2.0 * ratio), 1.0 + (ratio - 1.0) * 1e-9}) {
      const auto shape = ellc::hertz_shape({1.0, r}, HertzMode::hale);
      const long double log_ratio = std::log(static_cast<long double>(r));
      const long double f1 = 1.0L - std::pow(std::expm1(0.0602L * log_ratio), 1.456L);
      const long double f2 = 1.0L - std::pow(std::expm1(0.0684L * log_ratio), 1.531L);
      const long double e2 = -std::expm1(-(4.0L / 3.0L) * log_ratio);
      // Beyond B/A ~ 10⁴, f2 = 1 − X with X → 1 (and below): 1 − X keeps the rounding of X, ~1 ulp.
      const double tolerance = r < 1e4 ? 4e-16 : 1e-15;
      EXPECT_NEAR(shape.f1, static_cast<double>(f1), tolerance) << "B/A = " << r;
      EXPECT_NEAR(shape.f2, static_cast<double>(f2), tolerance) << "B/A = " << r;
      EXPECT_NEAR(shape.eccentricity_sq, static_cast<double>(e2), 4e-16 * static_cast<double>(e2)) << "B/A = " << r;
    }
  }
}

TEST(Hertz, RelativeCurvatureEqualsHalfTheEigenvaluesOfTheCurvatureTensorSum) {
  // The gap between two quadric surfaces is ½ xᵀ(C_I + C_J)x = A x² + B y², so A, B are half the
  // eigenvalues of the summed curvature tensors — an independent route to eq. (5).
  auto tensor = [](double k1, double k2, double angle) {
    Eigen::Matrix2d rotation;
    rotation << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
    return Eigen::Matrix2d(rotation * Eigen::Vector2d(k1, k2).asDiagonal() * rotation.transpose());
  };
  for (double alpha : {0.0, 0.3, 0.7854, 1.2, M_PI / 2, 2.5}) {
    const Eigen::Matrix2d sum = tensor(0.3, 0.1, 0.4 + alpha) + tensor(0.25, 0.05, 0.4);
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> solver(sum);
    const auto curvature = ellc::relative_curvature({0.3, 0.1}, {0.25, 0.05}, alpha);
    EXPECT_NEAR(curvature.a_sum, 0.5 * solver.eigenvalues()(0), 1e-15) << alpha;
    EXPECT_NEAR(curvature.b_sum, 0.5 * solver.eigenvalues()(1), 1e-15) << alpha;
    // The tensor form the narrow phase uses is the same eq. (5).
    const auto from_tensor = ellc::relative_curvature_from_tensor(sum(0, 0), sum(0, 1), sum(1, 1));
    EXPECT_NEAR(from_tensor.a_sum, curvature.a_sum, 1e-15) << alpha;
    EXPECT_NEAR(from_tensor.b_sum, curvature.b_sum, 1e-15) << alpha;
    const auto swapped = ellc::relative_curvature({0.25, 0.05}, {0.3, 0.1}, -alpha);
    EXPECT_NEAR(swapped.a_sum, curvature.a_sum, 1e-16);
    EXPECT_NEAR(swapped.b_sum, curvature.b_sum, 1e-16);
  }
}

TEST(Hertz, PressureFieldIntegratesToTheForce) {
  const auto shape = ellc::hertz_shape({0.04, 0.1}, HertzMode::exact);
  const auto contact = ellc::hertz_contact(shape, kModulus, 0.25);
  // Midpoint rule over the ellipse in scaled coordinates.
  const int n = 800;
  double integral = 0.0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double u = -1.0 + (i + 0.5) * 2.0 / n, v = -1.0 + (j + 0.5) * 2.0 / n;
      integral += ellc::hertz_pressure(contact.semi_axis_major, contact.semi_axis_minor, contact.peak_pressure,
                                       u * contact.semi_axis_major, v * contact.semi_axis_minor);
    }
  integral *= (2.0 / n) * (2.0 / n) * contact.semi_axis_major * contact.semi_axis_minor;
  EXPECT_NEAR(integral / contact.force, 1.0, 2e-4);
}

// ShapeParts::without_axes (the DEM's contact constants) skips Hale's e² only: R_e, f1 and f2
// are the same bits, over both branches of Hale's fit (B/A below and above e^{0.5/0.0684}).
TEST(Hertz, ShapeWithoutAxesKeepsTheLawsPartsBitForBit) {
  using ellc::HertzShape, ellc::RelativeCurvature, ellc::ShapeParts, ellc::hertz_shape;
  const auto same = [](double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; };
  for (const double ratio : {1.0, 1.0 + 1e-9, 1.2, 1.68, 1.7, 3.0, 100.0, 1400.0, 1600.0, 1e5}) {
    const RelativeCurvature curvature{0.1, 0.1 * ratio};
    for (const HertzMode mode : {HertzMode::hale, HertzMode::exact}) {
      const HertzShape all = hertz_shape(curvature, mode);
      const HertzShape lean = hertz_shape(curvature, mode, ShapeParts::without_axes);
      SCOPED_TRACE(testing::Message() << "B/A " << ratio << (mode == HertzMode::hale ? " hale" : " exact"));
      EXPECT_TRUE(same(lean.equivalent_radius, all.equivalent_radius));
      EXPECT_TRUE(same(lean.f1, all.f1));
      EXPECT_TRUE(same(lean.f2, all.f2));
      EXPECT_TRUE(std::isfinite(all.eccentricity_sq));
      if (mode == HertzMode::hale)
        EXPECT_TRUE(std::isnan(lean.eccentricity_sq));
      else
        EXPECT_TRUE(same(lean.eccentricity_sq, all.eccentricity_sq));
    }
  }
}

}  // namespace
