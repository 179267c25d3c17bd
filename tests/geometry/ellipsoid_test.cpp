// Ellipsoid queries: surface points, support points, curvatures against finite differences of
// the surface, umbilics, bounds, volume.

#include "ellc/geometry/ellipsoid.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numbers>

#include "support/geometry_support.hpp"

namespace ellc {
namespace {

using test::Rng;

Ellipsoid random_ellipsoid(Rng& rng) {
  return Ellipsoid(test::random_semi_axes(rng, test::uniform(rng, 0.5, 2.0)),
                   {Eigen::Vector3d(test::uniform(rng, -5, 5), test::uniform(rng, -5, 5), test::uniform(rng, -5, 5)),
                    test::random_orientation(rng)});
}

TEST(Ellipsoid, SurfacePointHasTheRequestedNormal) {
  Rng rng(1);
  for (int sample = 0; sample < 1000; ++sample) {
    const Ellipsoid body = random_ellipsoid(rng);
    const Eigen::Vector3d n = test::random_unit(rng);
    const Eigen::Vector3d p = body.surface_point_with_normal(n);
    EXPECT_NEAR(body.implicit_value(p), 0.0, 1e-13);
    EXPECT_LT((body.normal_at(p) - n).norm(), 1e-12);
    EXPECT_LT((body.support_point(3.7 * n) - p).norm(), 1e-12);
    EXPECT_NEAR(body.support_radius(n), (p - body.center()).dot(n), 1e-12);
  }
}

TEST(Ellipsoid, SupportPointMaximisesTheProjection) {
  Rng rng(2);
  for (int sample = 0; sample < 200; ++sample) {
    const Ellipsoid body = random_ellipsoid(rng);
    const Eigen::Vector3d direction = test::random_unit(rng);
    const double best = body.support_point(direction).dot(direction);
    for (int other = 0; other < 50; ++other) {
      const Eigen::Vector3d q = body.surface_point_with_normal(test::random_unit(rng));
      EXPECT_LE(q.dot(direction), best + 1e-12);
    }
  }
}

// Normal curvature along unit tangent t at surface point p with outward normal n, from the
// surface itself: step h along t, drop back onto the surface along −n by s (exact root of the
// quadratic), κ ≈ 2 s / h², averaged over ±h and Richardson-extrapolated in h.
double normal_section_curvature(const Ellipsoid& body, const Eigen::Vector3d& p, const Eigen::Vector3d& n,
                                const Eigen::Vector3d& t, double h) {
  auto drop = [&](double step) {
    const Eigen::Matrix3d rotation = body.rotation();
    const Eigen::Vector3d m = body.semi_axes().array().square().inverse();
    const Eigen::Vector3d q = rotation.transpose() * (p + step * t - body.center());
    const Eigen::Vector3d d = rotation.transpose() * n;
    const double qa = d.dot(m.cwiseProduct(d));
    const double qb = d.dot(m.cwiseProduct(q));
    const double qc = q.dot(m.cwiseProduct(q)) - 1.0;
    // (q − s d)ᵀ M (q − s d) = 1: the small root, written without cancellation.
    const double s = qc / (qb + std::sqrt(qb * qb - qa * qc));
    return 2.0 * s / (step * step);
  };
  // ±h cancels the odd (cubic) terms of the surface; Richardson then removes the h² term.
  auto symmetric = [&](double step) { return 0.5 * (drop(step) + drop(-step)); };
  return (4.0 * symmetric(0.5 * h) - symmetric(h)) / 3.0;
}

TEST(Ellipsoid, CurvaturesMatchFiniteDifferencesOfTheSurface) {
  Rng rng(3);
  for (int sample = 0; sample < 300; ++sample) {
    const Ellipsoid body = random_ellipsoid(rng);
    const Eigen::Vector3d n = test::random_unit(rng);
    const Eigen::Vector3d p = body.surface_point_with_normal(n);
    const SurfaceCurvature c = body.curvature_at(p);
    ASSERT_GE(c.kappa_1, c.kappa_2);
    ASSERT_GT(c.kappa_2, 0.0);
    EXPECT_NEAR(c.direction_1.norm(), 1.0, 1e-14);
    EXPECT_NEAR(c.direction_2.norm(), 1.0, 1e-14);
    EXPECT_NEAR(c.direction_1.dot(n), 0.0, 1e-13);
    EXPECT_NEAR(c.direction_2.dot(n), 0.0, 1e-13);
    EXPECT_NEAR(c.direction_1.dot(c.direction_2), 0.0, 1e-13);
    EXPECT_LT((c.direction_1.cross(c.direction_2) - n).norm(), 1e-12);  // (d1, d2, n) right-handed
    const double h = 1e-3 / c.kappa_1;
    for (int step = 0; step < 12; ++step) {  // Euler: κ(θ) = κ1 cos²θ + κ2 sin²θ
      const double theta = step * std::numbers::pi / 12.0;
      const Eigen::Vector3d t = std::cos(theta) * c.direction_1 + std::sin(theta) * c.direction_2;
      const double expected =
          c.kappa_1 * std::cos(theta) * std::cos(theta) + c.kappa_2 * std::sin(theta) * std::sin(theta);
      EXPECT_NEAR(normal_section_curvature(body, p, n, t, h), expected, 1e-7 * c.kappa_1) << "theta " << theta;
    }
    // The normal-only path gives the same.
    const SurfaceCurvature same = body.curvature_with_normal(n);
    EXPECT_NEAR(same.kappa_1, c.kappa_1, 1e-11 * c.kappa_1);
    EXPECT_NEAR(same.kappa_2, c.kappa_2, 1e-11 * c.kappa_1);
  }
}

TEST(Ellipsoid, TipCurvaturesAreTheClosedForm) {
  const Eigen::Vector3d axes(2.0, 1.0, 3.0);
  const Ellipsoid body(axes);
  const SurfaceCurvature c = body.curvature_at(Eigen::Vector3d(2.0, 0.0, 0.0));
  EXPECT_DOUBLE_EQ(c.kappa_1, 2.0 / 1.0);  // a/b² along y
  EXPECT_DOUBLE_EQ(c.kappa_2, 2.0 / 9.0);  // a/c² along z
  EXPECT_NEAR(std::abs(c.direction_1.y()), 1.0, 1e-15);
  EXPECT_NEAR(std::abs(c.direction_2.z()), 1.0, 1e-15);
  // Tip of the long axis c and a point on the equator of the x–y plane.
  const SurfaceCurvature top = body.curvature_at(Eigen::Vector3d(0.0, 0.0, 3.0));
  EXPECT_DOUBLE_EQ(top.kappa_1, 3.0 / 1.0);
  EXPECT_DOUBLE_EQ(top.kappa_2, 3.0 / 4.0);
}

TEST(Ellipsoid, UmbilicsGiveFiniteDeterministicDirections) {
  // Spheroid b = c: the x tips are umbilics. So is every point of a sphere.
  const Ellipsoid spheroid(Eigen::Vector3d(2.0, 1.0, 1.0),
                           {Eigen::Vector3d(1, 2, 3), Eigen::Quaterniond(0.3, 0.1, -0.5, 0.2)});
  const Eigen::Vector3d tip = spheroid.rotation().col(0);
  const SurfaceCurvature c = spheroid.curvature_with_normal(tip);
  EXPECT_TRUE(c.umbilic());
  EXPECT_DOUBLE_EQ(c.kappa_1, 2.0);
  EXPECT_DOUBLE_EQ(c.kappa_2, 2.0);
  EXPECT_TRUE(c.direction_1.allFinite() && c.direction_2.allFinite());
  EXPECT_NEAR(c.direction_1.norm(), 1.0, 1e-14);
  EXPECT_NEAR(c.direction_1.dot(tip), 0.0, 1e-14);
  const SurfaceCurvature again = spheroid.curvature_with_normal(tip);
  EXPECT_EQ(again.direction_1, c.direction_1);

  const Ellipsoid sphere(Eigen::Vector3d::Constant(0.5));
  Rng rng(4);
  for (int sample = 0; sample < 100; ++sample) {
    const SurfaceCurvature s = sphere.curvature_with_normal(test::random_unit(rng));
    EXPECT_NEAR(s.kappa_1, 2.0, 1e-14);
    EXPECT_NEAR(s.kappa_2, 2.0, 1e-14);
    EXPECT_TRUE(s.direction_1.allFinite());
  }
  // Approaching the umbilic, the curvatures converge continuously (no jump at the tolerance).
  double previous_split = 1.0;
  for (double angle = 1e-1; angle > 1e-9; angle *= 0.1) {
    const Eigen::Vector3d n = (tip + angle * spheroid.rotation().col(1)).normalized();
    const SurfaceCurvature near = spheroid.curvature_with_normal(n);
    const double split = near.kappa_1 - near.kappa_2;
    EXPECT_LT(split, previous_split);
    EXPECT_NEAR(near.kappa_1, 2.0, 10.0 * angle);
    previous_split = split;
  }
}

TEST(Ellipsoid, BoundsContainTheSurfaceAndAreTight) {
  Rng rng(5);
  for (int sample = 0; sample < 100; ++sample) {
    const Ellipsoid body = random_ellipsoid(rng);
    const AxisAlignedBox box = body.axis_aligned_bounds();
    const OrientedBox oriented = body.bounding_box();
    for (int k = 0; k < 3; ++k) {  // tight: the support points along ±world axes touch the box
      EXPECT_NEAR(body.support_point(Eigen::Vector3d::Unit(k))[k], box.upper[k], 1e-12);
      EXPECT_NEAR(body.support_point(-Eigen::Vector3d::Unit(k))[k], box.lower[k], 1e-12);
    }
    for (int point = 0; point < 100; ++point) {
      const Eigen::Vector3d p = body.surface_point_with_normal(test::random_unit(rng));
      EXPECT_LE((p - body.center()).norm(), body.bounding_radius() + 1e-12);
      EXPECT_TRUE(((p - box.lower).array() >= -1e-12).all() && ((box.upper - p).array() >= -1e-12).all());
      const Eigen::Vector3d local = oriented.axes.transpose() * (p - oriented.center);
      EXPECT_TRUE((local.cwiseAbs().array() <= oriented.half_extents.array() + 1e-12).all());
    }
  }
}

TEST(Ellipsoid, VolumeAndMeanRadius) {
  const Ellipsoid body(Eigen::Vector3d(1.0, 2.0, 4.0));
  EXPECT_DOUBLE_EQ(body.volume(), 4.0 / 3.0 * std::numbers::pi * 8.0);
  EXPECT_DOUBLE_EQ(body.mean_radius(), 2.0);
}

TEST(Ellipsoid, InvalidDataIsFlagged) {
  EXPECT_TRUE(Ellipsoid(Eigen::Vector3d(1, 2, 3)).valid());
  EXPECT_FALSE(Ellipsoid(Eigen::Vector3d(1, -2, 3)).valid());
  EXPECT_FALSE(Ellipsoid(Eigen::Vector3d(1, std::nan(""), 3)).valid());
  EXPECT_FALSE(Ellipsoid(Eigen::Vector3d(1, 2, 3), {Eigen::Vector3d::Zero(), Eigen::Quaterniond(0, 0, 0, 0)}).valid());
  EXPECT_FALSE(
      Ellipsoid(Eigen::Vector3d(1, 2, 3), {Eigen::Vector3d(0, INFINITY, 0), Eigen::Quaterniond::Identity()}).valid());
  // A non-unit quaternion is normalised.
  const Ellipsoid scaled(Eigen::Vector3d(1, 2, 3), {Eigen::Vector3d::Zero(), Eigen::Quaterniond(2, 0, 0, 0)});
  EXPECT_TRUE(scaled.valid());
  EXPECT_TRUE(scaled.rotation().isApprox(Eigen::Matrix3d::Identity()));
}

// moved_to (periodic images in the engines) is the ellipsoid built anew at the image's centre,
// bit for bit, and valid exactly when that one is.
TEST(Ellipsoid, MovedToIsTheEllipsoidBuiltAtTheNewCentre) {
  const auto same = [](const auto& a, const auto& b) {
    return std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<std::size_t>(a.size())) == 0;
  };
  const Eigen::Vector3d axes(1.5, 0.7, 2.2);
  const Eigen::Quaterniond turn(0.3, -0.8, 0.4, 1.1);  // not normalised: the constructor normalises it
  const Ellipsoid original(axes, {Eigen::Vector3d(0.25, -3.0, 7.5), turn});
  const Eigen::Vector3d image(100.25, -3.0, 7.5);
  const Ellipsoid moved = original.moved_to(image);
  const Ellipsoid built(axes, {image, turn});
  EXPECT_TRUE(same(moved.center(), built.center()));
  EXPECT_TRUE(same(moved.pose().orientation.coeffs(), built.pose().orientation.coeffs()));
  EXPECT_TRUE(same(moved.rotation(), built.rotation()));
  EXPECT_TRUE(same(moved.inverse_shape(), built.inverse_shape()));
  EXPECT_TRUE(same(moved.shape(), built.shape()));
  EXPECT_TRUE(moved.valid() && built.valid());
  EXPECT_TRUE(same(moved.normal_at(image + Eigen::Vector3d(0.3, 0.1, -0.2)),
                   built.normal_at(image + Eigen::Vector3d(0.3, 0.1, -0.2))));
  // Validity follows the new centre; bad semi-axes stay bad wherever the body goes.
  const Eigen::Vector3d nowhere(std::nan(""), 0.0, 0.0);
  EXPECT_FALSE(original.moved_to(nowhere).valid());
  EXPECT_TRUE(Ellipsoid(axes, {nowhere, turn}).moved_to(image).valid());
  EXPECT_FALSE(Ellipsoid(Eigen::Vector3d(1.0, -1.0, 1.0)).moved_to(image).valid());
}

// set_pose (the engine re-poses every particle in place each step) is the ellipsoid built anew
// with that pose, bit for bit, whatever the pose before; validity follows the new pose.
TEST(Ellipsoid, SetPoseIsTheEllipsoidBuiltWithThatPose) {
  const auto same = [](const auto& a, const auto& b) {
    return std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<std::size_t>(a.size())) == 0;
  };
  const Eigen::Vector3d axes(1.5, 0.7, 2.2);
  Ellipsoid reposed(axes, {Eigen::Vector3d(std::nan(""), 0.0, 0.0), Eigen::Quaterniond(0.0, 0.0, 0.0, 0.0)});
  EXPECT_FALSE(reposed.valid());
  for (const Pose& pose : {Pose{Eigen::Vector3d(0.25, -3.0, 7.5), Eigen::Quaterniond(0.3, -0.8, 0.4, 1.1)},
                           Pose{Eigen::Vector3d(-1.0, 2.0, 0.5), Eigen::Quaterniond(-0.9, 0.1, 0.05, -0.2)}}) {
    reposed.set_pose(pose);
    const Ellipsoid built(axes, pose);
    EXPECT_TRUE(same(reposed.center(), built.center()));
    EXPECT_TRUE(same(reposed.pose().orientation.coeffs(), built.pose().orientation.coeffs()));
    EXPECT_TRUE(same(reposed.rotation(), built.rotation()));
    EXPECT_TRUE(same(reposed.inverse_shape(), built.inverse_shape()));
    EXPECT_TRUE(same(reposed.shape(), built.shape()));
    EXPECT_TRUE(reposed.valid() && built.valid());
  }
  reposed.set_pose({Eigen::Vector3d::Zero(), Eigen::Quaterniond(0.0, 0.0, 0.0, 0.0)});
  EXPECT_FALSE(reposed.valid());
  Ellipsoid flat(Eigen::Vector3d(1.0, 0.0, 1.0));
  flat.set_pose({});
  EXPECT_FALSE(flat.valid());
}

}  // namespace
}  // namespace ellc
