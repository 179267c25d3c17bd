// Carlson's integrals against the C++17 special functions (an independent implementation).
#include <gtest/gtest.h>

#include <cmath>

#include "ellc/hertz/elliptic_integrals.hpp"

namespace {
TEST(EllipticIntegrals, CompleteIntegralsMatchTheStandardLibrary) {
  for (double k : {0.0, 0.1, 0.5, 0.8, 0.95, 0.999}) {
    const double q = 1.0 - k * k;
    const double rf = ellc::elliptic::carlson_rf(0.0, q, 1.0);
    const double rd = ellc::elliptic::carlson_rd(0.0, q, 1.0);
    const double big_k = std::comp_ellint_1(k);  // takes the modulus k, not m = k²
    const double big_e = std::comp_ellint_2(k);
    EXPECT_NEAR(rf, big_k, 1e-14 * big_k) << k;
    // E = R_F − (m/3) R_D cancels a little as k → 1; K − E, which the library uses, does not.
    EXPECT_NEAR(rf - k * k / 3.0 * rd, big_e, 1e-13 * big_e) << k;
  }
}

TEST(EllipticIntegrals, KnownClosedForms) {
  // R_F(0, 1, 1) = π/2, R_D(0, 1, 1) = 3π/4, R_F(1, 1, 1) = 1, R_D(1, 1, 1) = 1.
  EXPECT_NEAR(ellc::elliptic::carlson_rf(0.0, 1.0, 1.0), M_PI / 2.0, 1e-15);
  EXPECT_NEAR(ellc::elliptic::carlson_rd(0.0, 1.0, 1.0), 3.0 * M_PI / 4.0, 1e-15);
  EXPECT_NEAR(ellc::elliptic::carlson_rf(1.0, 1.0, 1.0), 1.0, 1e-15);
  EXPECT_NEAR(ellc::elliptic::carlson_rd(1.0, 1.0, 1.0), 1.0, 1e-15);
}
}  // namespace
