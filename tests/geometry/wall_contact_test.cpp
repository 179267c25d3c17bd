// Ellipsoid–wall contact (geometry only; the law on walls is tests/contact/normal_contact_test.cpp).

#include "ellc/geometry/wall_contact.hpp"

#include <gtest/gtest.h>

#include "support/geometry_support.hpp"

namespace ellc {
namespace {

TEST(WallContact, SphereOnAPlaneIsExact) {
  test::Rng rng(30);
  for (int sample = 0; sample < 500; ++sample) {
    const double radius = test::uniform(rng, 0.1, 3.0);
    const Eigen::Vector3d up = test::random_unit(rng);
    const Plane wall{Eigen::Vector3d(1, 2, 3), up};
    const double overlap = test::uniform(rng, -0.2, 0.2) * radius;
    const Eigen::Vector3d centre =
        wall.point + (radius - overlap) * up + test::uniform(rng, -5, 5) * up.unitOrthogonal();
    const NarrowPhaseResult result =
        wall_contact(Ellipsoid(Eigen::Vector3d::Constant(radius), {centre, test::random_orientation(rng)}), wall);
    EXPECT_NEAR(result.geometry.overlap, overlap, 1e-14 * (1.0 + centre.norm()));
    EXPECT_LT((result.geometry.normal + up).norm(), 1e-15);
    EXPECT_NEAR((result.geometry.surface_point_j - wall.point).dot(up), 0.0, 1e-14 * (1.0 + centre.norm()));
    if (overlap > 1e-12) {
      ASSERT_EQ(result.status, NarrowPhaseStatus::contact);
      EXPECT_NEAR(result.geometry.curvature_i.kappa_1, 1.0 / radius, 1e-13 / radius);
      EXPECT_EQ(result.geometry.curvature_j.kappa_1, 0.0);
      EXPECT_EQ(result.geometry.curvature_j.kappa_2, 0.0);
      EXPECT_EQ(result.geometry.alpha, 0.0);
    } else if (overlap < -1e-12) {
      EXPECT_EQ(result.status, NarrowPhaseStatus::separated);
    }
  }
}

TEST(WallContact, BadWallFails) {
  const Ellipsoid body(Eigen::Vector3d(1, 1, 1));
  EXPECT_EQ(wall_contact(body, Plane{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()}).status,
            NarrowPhaseStatus::failed);
  EXPECT_EQ(wall_contact(body, Plane{Eigen::Vector3d(NAN, 0, 0), Eigen::Vector3d::UnitZ()}).status,
            NarrowPhaseStatus::failed);
  // A non-unit wall normal is normalised.
  const NarrowPhaseResult scaled =
      wall_contact(body, Plane{Eigen::Vector3d(0, 0, -0.9), 5.0 * Eigen::Vector3d::UnitZ()});
  ASSERT_EQ(scaled.status, NarrowPhaseStatus::contact);
  EXPECT_NEAR(scaled.geometry.overlap, 0.1, 1e-15);
}

}  // namespace
}  // namespace ellc
