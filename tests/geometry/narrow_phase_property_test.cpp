// Issue 19, items 6 and 8: the narrow phase over the documented shape range (aspect up to 1:100).
// The 10⁶-pair run is the documented command `narrow_phase_property` (docs/geometry.md §6).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "ellc/geometry/narrow_phase.hpp"
#include "narrow_phase_property.hpp"
#include "support/geometry_support.hpp"

namespace ellc {
namespace {

// 10⁴ pairs: no NaN, every result verified, swap-symmetric, and no failure for separated,
// grazing or overlaps up to 10 % of the smallest semi-axis.
TEST(NarrowPhaseProperty, TenThousandPairsUpToAspectOneHundred) {
  const test::PropertyReport report = test::run_narrow_phase_property(10'000, 19);
  std::fputs(report.text().c_str(), stdout);
  const test::PropertyCell all = report.total();
  EXPECT_EQ(all.pairs, 10'000);
  EXPECT_EQ(all.non_finite, 0);
  EXPECT_EQ(all.unverified, 0);
  EXPECT_EQ(all.swap_mismatch, 0);
  EXPECT_EQ(report.required_failures(), 0);
  EXPECT_LT(report.max_swap_overlap_difference, 1e-12);
}

// The defect of the review: round discs 100:1 (a = b = 100 c) in shallow contact, 1–10 % of c,
// random poses. The old solve crawled along the flat valley of g (Levenberg-damped steps of
// ~1e-3 rad) and gave up after 40 steps in ~0.1 % of these pairs; now none fails.
TEST(NarrowPhaseProperty, ShallowContactsOfHundredToOneDiscsAndNeedlesConverge) {
  test::Rng rng(100);
  long failed = 0;
  long pairs = 0;
  for (const bool disc : {true, false}) {
    for (int sample = 0; sample < 10'000; ++sample) {
      const Eigen::Vector3d shape = disc ? Eigen::Vector3d(1.0, 1.0, 0.01) : Eigen::Vector3d(1.0, 0.01, 0.01);
      const Eigen::Vector3d axes_i = shape * test::uniform(rng, 0.5, 2.0);
      const Eigen::Vector3d axes_j = shape * test::uniform(rng, 0.5, 2.0);
      const double overlap = test::uniform(rng, 0.01, 0.1) * std::min(axes_i.minCoeff(), axes_j.minCoeff());
      const Ellipsoid i(axes_i, {Eigen::Vector3d::Zero(), test::random_orientation(rng)});
      const Ellipsoid j =
          test::place_partner(i, axes_j, test::random_orientation(rng), test::random_unit(rng), overlap);
      const NarrowPhaseResult result = ellipsoid_contact(i, j);
      ++pairs;
      if (result.status == NarrowPhaseStatus::failed) ++failed;
      EXPECT_TRUE(std::isfinite(result.geometry.overlap) && result.geometry.normal.allFinite());
    }
  }
  EXPECT_EQ(failed, 0) << "of " << pairs;
}

}  // namespace
}  // namespace ellc
