// normal_contact(): from a contact geometry to the law's force, on walls and when separated.

#include "ellc/contact/normal_contact.hpp"

#include <gtest/gtest.h>

#include "ellc/geometry/tip_contact.hpp"
#include "ellc/geometry/wall_contact.hpp"
#include "support/geometry_support.hpp"
#include "support/nmc.hpp"

namespace ellc {
namespace {

TEST(NormalContact, TipOnAWallIsHertzWithAFlat) {
  // Ellipsoid with its a-axis along the wall normal: curvatures a/b², a/c² against zero.
  const Eigen::Vector3d axes(3.0, 2.0, 4.0);
  const double overlap = 0.05;
  const Ellipsoid body(axes, {Eigen::Vector3d(0, 0, 3.0 - overlap),
                              Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitZ())});
  const NarrowPhaseResult result = wall_contact(body, Plane{Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ()});
  ASSERT_EQ(result.status, NarrowPhaseStatus::contact);
  EXPECT_NEAR(result.geometry.overlap, overlap, 1e-15);
  EXPECT_DOUBLE_EQ(result.geometry.curvature_i.kappa_1, 3.0 / 4.0);
  EXPECT_DOUBLE_EQ(result.geometry.curvature_i.kappa_2, 3.0 / 16.0);

  const ContactMaterial mixed = mix(test::kNmc, test::kNmc);
  EXPECT_DOUBLE_EQ(wall_mean_radius_sum(body), 2.0 * mean_radius(axes));
  const NormalContact contact =
      normal_contact(result.geometry, mixed, wall_mean_radius_sum(body), HertzMode::hale, LawParameters{}, 0.0);
  const ContactConstants expected = make_contact_constants(mixed, tip_curvatures(axes), PrincipalCurvatures{0.0, 0.0},
                                                           0.0, 2.0 * mean_radius(axes), HertzMode::hale);
  EXPECT_NEAR(contact.constants.equivalent_radius, expected.equivalent_radius, 1e-12 * expected.equivalent_radius);
  EXPECT_NEAR(contact.constants.f1, expected.f1, 1e-12);
  EXPECT_NEAR(contact.law.force, evaluate_contact(expected, overlap, 0.0).force, 1e-12 * contact.law.force);
  EXPECT_LT((contact.force_on_j + contact.law.force * Eigen::Vector3d::UnitZ()).norm(), 1e-12 * contact.law.force);
  EXPECT_NEAR(contact.application_point.z(), -overlap / 2.0, 1e-15);
}

TEST(NormalContactWiring, SeparatedGeometryGivesNoForce) {
  ContactGeometry geometry;
  geometry.overlap = -0.1;
  geometry.curvature_i = SurfaceCurvature{1.0, 1.0};
  geometry.curvature_j = SurfaceCurvature{1.0, 1.0};
  geometry.relative = {1.0, 1.0};
  const NormalContact contact = normal_contact(geometry, ContactMaterial{1e5, 1e3}, 2.0, HertzMode::hale, LawParameters{}, 0.0);
  EXPECT_EQ(contact.law.force, 0.0);
  EXPECT_EQ(contact.law.regime, Regime::separated);
  EXPECT_EQ(contact.force_on_j, Eigen::Vector3d::Zero());
}

}  // namespace
}  // namespace ellc
