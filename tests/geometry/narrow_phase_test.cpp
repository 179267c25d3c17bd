// Ellipsoid–ellipsoid narrow phase: spheres exactly, constructed common normals, rigid-motion
// invariance, I↔J swap, warm starts, separation, degenerate input.

#include "ellc/geometry/narrow_phase.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <type_traits>

#include "ellc/geometry/contact_function.hpp"
#include "support/geometry_support.hpp"

namespace ellc {
namespace {

using test::Rng;

// The engine stores one warm start per pair: a small trivially copyable value, cold by default.
static_assert(std::is_trivially_copyable_v<NarrowPhaseWarmStart>);
static_assert(std::is_standard_layout_v<NarrowPhaseWarmStart>);
static_assert(sizeof(NarrowPhaseWarmStart) <= 32);

void expect_finite(const NarrowPhaseResult& result) {
  const ContactGeometry& g = result.geometry;
  EXPECT_TRUE(g.point.allFinite() && g.normal.allFinite() && std::isfinite(g.overlap) &&
              g.surface_point_i.allFinite() && g.surface_point_j.allFinite() && std::isfinite(g.alpha) &&
              std::isfinite(g.curvature_i.kappa_1) && std::isfinite(g.curvature_j.kappa_1) &&
              g.curvature_i.direction_1.allFinite() && g.curvature_j.direction_1.allFinite());
}

TEST(NarrowPhase, SpherePairIsExact) {
  Rng rng(10);
  for (int sample = 0; sample < 1000; ++sample) {
    const double radius_i = test::uniform(rng, 0.2, 2.0);
    const double radius_j = test::uniform(rng, 0.2, 2.0);
    const Eigen::Vector3d n = test::random_unit(rng);
    const double overlap = test::uniform(rng, -0.1, 0.2) * std::min(radius_i, radius_j);
    const Eigen::Vector3d ci(test::uniform(rng, -3, 3), test::uniform(rng, -3, 3), test::uniform(rng, -3, 3));
    const Eigen::Vector3d cj = ci + (radius_i + radius_j - overlap) * n;
    const Ellipsoid i(Eigen::Vector3d::Constant(radius_i), {ci, test::random_orientation(rng)});
    const Ellipsoid j(Eigen::Vector3d::Constant(radius_j), {cj, test::random_orientation(rng)});
    const NarrowPhaseResult result = ellipsoid_contact(i, j);
    expect_finite(result);
    const double exact = radius_i + radius_j - (cj - ci).norm();
    if (exact > 0.0) {
      ASSERT_EQ(result.status, NarrowPhaseStatus::contact);
      EXPECT_NEAR(result.geometry.overlap, exact, 1e-14 * (radius_i + radius_j));
      EXPECT_LT((result.geometry.normal - (cj - ci).normalized()).norm(), 1e-13);
      EXPECT_LT((result.geometry.surface_point_i - (ci + radius_i * result.geometry.normal)).norm(), 1e-13);
      EXPECT_LT((result.geometry.surface_point_j - (cj - radius_j * result.geometry.normal)).norm(), 1e-13);
      EXPECT_NEAR(result.geometry.curvature_i.kappa_1, 1.0 / radius_i, 1e-13 / radius_i);
      EXPECT_NEAR(result.geometry.curvature_i.kappa_2, 1.0 / radius_i, 1e-13 / radius_i);
      EXPECT_NEAR(result.geometry.curvature_j.kappa_1, 1.0 / radius_j, 1e-13 / radius_j);
      EXPECT_EQ(result.geometry.alpha, 0.0);  // both sides umbilic: α is 0, not noise
    } else {
      EXPECT_EQ(result.status, NarrowPhaseStatus::separated);
      EXPECT_LE(result.geometry.overlap, 0.0);
      EXPECT_GE(result.geometry.overlap, exact - 1e-14);  // |overlap| ≤ distance
    }
  }
}

TEST(NarrowPhase, RecoversAConstructedCommonNormal) {
  Rng rng(11);
  int recovered = 0;
  constexpr int kSamples = 2000;
  for (int sample = 0; sample < kSamples; ++sample) {
    const Ellipsoid i(test::random_semi_axes(rng, 1.0), {Eigen::Vector3d::Zero(), test::random_orientation(rng)});
    const Eigen::Vector3d n = test::random_unit(rng);
    const double overlap = test::uniform(rng, 0.0, 0.05);  // small: the constructed normal is the minimum
    const Ellipsoid j =
        test::place_partner(i, test::random_semi_axes(rng, 1.0), test::random_orientation(rng), n, overlap);
    const NarrowPhaseResult result = ellipsoid_contact(i, j);
    ASSERT_EQ(result.status, NarrowPhaseStatus::contact);
    expect_finite(result);
    if (std::abs(result.geometry.overlap - overlap) < 1e-12 && (result.geometry.normal - n).norm() < 1e-9) ++recovered;
    // Whatever was found is a genuine common normal.
    const ContactGeometry& g = result.geometry;
    EXPECT_LT((i.normal_at(g.surface_point_i) - g.normal).norm(), 1e-10);
    EXPECT_LT((j.normal_at(g.surface_point_j) + g.normal).norm(), 1e-10);
    const Eigen::Vector3d joining = g.surface_point_i - g.surface_point_j;
    EXPECT_LT((joining - joining.dot(g.normal) * g.normal).norm(), 1e-12);
    EXPECT_NEAR(joining.dot(g.normal), g.overlap, 1e-13);
    EXPECT_LE(g.overlap, overlap + 1e-13);  // never deeper than the constructed one
  }
  EXPECT_GE(recovered, kSamples * 99 / 100);
}

struct Pair {
  Ellipsoid i;
  Ellipsoid j;
};

Pair random_pair(Rng& rng, double overlap) {
  const Ellipsoid i(test::random_semi_axes(rng, 1.0),
                    {Eigen::Vector3d(test::uniform(rng, -2, 2), 0.5, 1.0), test::random_orientation(rng)});
  return {i, test::place_partner(i, test::random_semi_axes(rng, 0.8), test::random_orientation(rng),
                                 test::random_unit(rng), overlap)};
}

Ellipsoid moved(const Ellipsoid& body, const Eigen::Quaterniond& rotation, const Eigen::Vector3d& translation) {
  return Ellipsoid(body.semi_axes(), {rotation * body.center() + translation, rotation * body.pose().orientation});
}

TEST(NarrowPhase, InvariantUnderARigidMotionOfBothBodies) {
  Rng rng(12);
  for (int sample = 0; sample < 500; ++sample) {
    const Pair pair = random_pair(rng, test::uniform(rng, 0.0, 0.15));
    const Eigen::Quaterniond rotation = test::random_orientation(rng);
    const Eigen::Vector3d translation(test::uniform(rng, -10, 10), test::uniform(rng, -10, 10),
                                      test::uniform(rng, -10, 10));
    const NarrowPhaseResult a = ellipsoid_contact(pair.i, pair.j);
    const NarrowPhaseResult b =
        ellipsoid_contact(moved(pair.i, rotation, translation), moved(pair.j, rotation, translation));
    ASSERT_EQ(a.status, NarrowPhaseStatus::contact);
    ASSERT_EQ(b.status, NarrowPhaseStatus::contact);
    const Eigen::Matrix3d r = rotation.toRotationMatrix();
    EXPECT_NEAR(a.geometry.overlap, b.geometry.overlap, 1e-12);
    EXPECT_LT((r * a.geometry.normal - b.geometry.normal).norm(), 1e-10);
    EXPECT_LT((r * a.geometry.point + translation - b.geometry.point).norm(), 1e-10);
    EXPECT_NEAR(a.geometry.curvature_i.kappa_1, b.geometry.curvature_i.kappa_1, 1e-9 * a.geometry.curvature_i.kappa_1);
    EXPECT_NEAR(a.geometry.curvature_i.kappa_2, b.geometry.curvature_i.kappa_2, 1e-9 * a.geometry.curvature_i.kappa_1);
    EXPECT_NEAR(a.geometry.curvature_j.kappa_1, b.geometry.curvature_j.kappa_1, 1e-9 * a.geometry.curvature_j.kappa_1);
    EXPECT_NEAR(a.geometry.curvature_j.kappa_2, b.geometry.curvature_j.kappa_2, 1e-9 * a.geometry.curvature_j.kappa_1);
    EXPECT_NEAR(a.geometry.alpha, b.geometry.alpha, 1e-7);
    // Principal directions are lines: equal up to sign.
    EXPECT_NEAR(std::abs((r * a.geometry.curvature_i.direction_1).dot(b.geometry.curvature_i.direction_1)), 1.0, 1e-8);
  }
}

TEST(NarrowPhase, SwappingIAndJChangesNothing) {
  Rng rng(13);
  for (int sample = 0; sample < 500; ++sample) {
    const Pair pair = random_pair(rng, test::uniform(rng, 0.0, 0.15));
    const NarrowPhaseResult a = ellipsoid_contact(pair.i, pair.j);
    const NarrowPhaseResult b = ellipsoid_contact(pair.j, pair.i);
    ASSERT_EQ(a.status, NarrowPhaseStatus::contact);
    ASSERT_EQ(b.status, NarrowPhaseStatus::contact);
    EXPECT_NEAR(a.geometry.overlap, b.geometry.overlap, 1e-12);
    EXPECT_LT((a.geometry.normal + b.geometry.normal).norm(), 1e-10);
    EXPECT_LT((a.geometry.point - b.geometry.point).norm(), 1e-10);
    EXPECT_LT((a.geometry.surface_point_i - b.geometry.surface_point_j).norm(), 1e-10);
    EXPECT_NEAR(a.geometry.curvature_i.kappa_1, b.geometry.curvature_j.kappa_1, 1e-9 * a.geometry.curvature_i.kappa_1);
    EXPECT_NEAR(a.geometry.curvature_j.kappa_2, b.geometry.curvature_i.kappa_2, 1e-9 * a.geometry.curvature_j.kappa_1);
    EXPECT_NEAR(a.geometry.alpha, b.geometry.alpha, 1e-7);
  }
}

// 200 random contacts, each followed for 20 steps in which J moves by 10⁻³ and turns by `turn`
// rad: `solve(i, j, previous)` returns the new result, which becomes `previous` for the next step.
template <typename Solve>
void follow_moving_contacts(std::uint64_t seed, double turn, Solve&& solve) {
  Rng rng(seed);
  for (int sample = 0; sample < 200; ++sample) {
    Pair pair = random_pair(rng, 0.05);
    NarrowPhaseResult previous = ellipsoid_contact(pair.i, pair.j);
    ASSERT_EQ(previous.status, NarrowPhaseStatus::contact);
    const Eigen::Vector3d velocity = 1e-3 * test::random_unit(rng);
    const Eigen::Quaterniond spin(Eigen::AngleAxisd(turn, test::random_unit(rng)));
    for (int step = 0; step < 20; ++step) {
      pair.j = Ellipsoid(pair.j.semi_axes(), {pair.j.center() + velocity, spin * pair.j.pose().orientation});
      previous = solve(pair.i, pair.j, previous);
    }
  }
}

TEST(NarrowPhase, WarmStartFollowsAMovingContact) {
  follow_moving_contacts(14, 1e-3, [](const Ellipsoid& i, const Ellipsoid& j, const NarrowPhaseResult& previous) {
    const NarrowPhaseResult warm = ellipsoid_contact(i, j, &previous.warm_start);
    const NarrowPhaseResult cold = ellipsoid_contact(i, j);
    EXPECT_EQ(warm.status, cold.status);
    EXPECT_FALSE(warm.cold_start);
    EXPECT_LE(warm.iterations, 3);
    EXPECT_NEAR(warm.geometry.overlap, cold.geometry.overlap, 1e-12);
    if (warm.status == NarrowPhaseStatus::contact) {
      EXPECT_LT((warm.geometry.normal - cold.geometry.normal).norm(), 1e-10);
    }
    return warm;
  });
}

TEST(NarrowPhase, SeparatedPairsGiveASeparatingAxis) {
  Rng rng(15);
  for (int sample = 0; sample < 1000; ++sample) {
    const double gap = test::uniform(rng, 1e-9, 0.5);
    const Pair pair = random_pair(rng, -gap);
    const NarrowPhaseResult result = ellipsoid_contact(pair.i, pair.j);
    ASSERT_EQ(result.status, NarrowPhaseStatus::separated);
    expect_finite(result);
    const Eigen::Vector3d& n = result.geometry.normal;
    const double reach =
        pair.i.support_radius(n) + pair.j.support_radius(-n) - n.dot(pair.j.center() - pair.i.center());
    EXPECT_LT(reach, 0.0);
    EXPECT_NEAR(result.geometry.overlap, reach, 1e-12);
    EXPECT_GE(result.geometry.overlap, -gap - 1e-12);  // the gap is the distance: |overlap| ≤ it
    // A warm start from a separating axis returns at once.
    const NarrowPhaseResult again = ellipsoid_contact(pair.i, pair.j, &result.warm_start);
    EXPECT_EQ(again.status, NarrowPhaseStatus::separated);
    EXPECT_EQ(again.iterations, 0);
  }
}

// overlap_along(n) is g(n), whose minimum over n is the common-normal overlap: it equals the
// solved overlap along the solved normal, is not below it along nearby axes, and sees J only
// through the offset given (a periodic image of J is J shifted).
TEST(NarrowPhase, OverlapAlongAnAxisIsBoundedByTheCommonNormal) {
  Rng rng(16);
  for (int sample = 0; sample < 1000; ++sample) {
    const Pair pair = random_pair(rng, test::uniform(rng, -0.3, 0.3));
    const NarrowPhaseResult result = ellipsoid_contact(pair.i, pair.j);
    ASSERT_NE(result.status, NarrowPhaseStatus::failed);
    const Eigen::Vector3d offset = pair.j.center() - pair.i.center();
    const double scale = pair.i.bounding_radius() + pair.j.bounding_radius();
    EXPECT_NEAR(overlap_along(pair.i, pair.j, offset, result.geometry.normal), result.geometry.overlap, 1e-12 * scale);
    if (result.status == NarrowPhaseStatus::contact) {  // the common normal is a (local) minimum of g
      for (int axis = 0; axis < 20; ++axis) {
        const Eigen::Vector3d n = (result.geometry.normal + 0.02 * test::random_unit(rng)).normalized();
        EXPECT_GE(overlap_along(pair.i, pair.j, offset, n), result.geometry.overlap - 1e-12 * scale);
      }
    }
    const Eigen::Vector3d shift(37.0, -11.0, 0.0);  // J moved away by a box period: only the offset counts
    const Ellipsoid image(pair.j.semi_axes(), {pair.j.center() + shift, pair.j.pose().orientation});
    EXPECT_NEAR(overlap_along(pair.i, pair.j, offset + shift, result.geometry.normal),
                overlap_along(pair.i, image, offset + shift, result.geometry.normal), 1e-12 * scale);
  }
}

// A, B come from the summed curvature tensors; they must be eq. (5) of the two sides' own
// principal curvatures and α, which the narrow phase reports beside them.
TEST(NarrowPhase, RelativeCurvatureIsEquationFiveOfTheSides) {
  Rng rng(18);
  for (int sample = 0; sample < 1000; ++sample) {
    const Pair pair = random_pair(rng, test::uniform(rng, 0.01, 0.3));
    const NarrowPhaseResult result = ellipsoid_contact(pair.i, pair.j);
    if (result.status != NarrowPhaseStatus::contact) continue;
    const ContactGeometry& g = result.geometry;
    const RelativeCurvature eq5 = relative_curvature(g.curvature_i.principal(), g.curvature_j.principal(), g.alpha);
    EXPECT_NEAR(g.relative.a_sum, eq5.a_sum, 1e-12 * eq5.b_sum);
    EXPECT_NEAR(g.relative.b_sum, eq5.b_sum, 1e-12 * eq5.b_sum);
  }
}

// The DEM options: one Newton step from last step's normal. Against the solve to rounding, the
// normal stays within ~|step|² (the normal turns by up to ~10⁻³ rad per step here, so 10⁻⁶; the
// bound leaves a factor 3) and the overlap, stationary in n, within rounding; the per-side
// curvatures are skipped, A and B are not.
TEST(NarrowPhase, TimeSteppingOptionsStayCloseToTheSolveToRounding) {
  constexpr NarrowPhaseOptions kEngineOptions{1e-3, false};  // the DEM engine's defaults (settings.hpp)
  int solves = 0;
  int newton_steps = 0;
  follow_moving_contacts(19, 3e-4, [&](const Ellipsoid& i, const Ellipsoid& j, const NarrowPhaseResult& previous) {
    const NarrowPhaseResult fast = ellipsoid_contact(i, j, &previous.warm_start, kEngineOptions);
    const NarrowPhaseResult exact = ellipsoid_contact(i, j);
    EXPECT_EQ(fast.status, exact.status);
    if (fast.status != NarrowPhaseStatus::contact || exact.status != NarrowPhaseStatus::contact) return fast;
    ++solves;
    newton_steps += fast.iterations;
    const double scale = i.bounding_radius() + j.bounding_radius();
    EXPECT_LT((fast.geometry.normal - exact.geometry.normal).norm(), 3e-6);
    EXPECT_NEAR(fast.geometry.overlap, exact.geometry.overlap, 1e-12 * scale);
    EXPECT_NEAR(fast.geometry.relative.a_sum, exact.geometry.relative.a_sum, 1e-5 * exact.geometry.relative.b_sum);
    EXPECT_NEAR(fast.geometry.relative.b_sum, exact.geometry.relative.b_sum, 1e-5 * exact.geometry.relative.b_sum);
    EXPECT_EQ(fast.geometry.curvature_i.kappa_1, 0.0);  // skipped
    return fast;
  });
  ASSERT_GT(solves, 1000);
  EXPECT_LT(newton_steps, 1.2 * solves) << "about one Newton step per time step";
}

TEST(NarrowPhase, DegenerateInputIsReportedNotComputed) {
  const Ellipsoid good(Eigen::Vector3d(1, 2, 3));
  const Ellipsoid bad(Eigen::Vector3d(1, 0, 3));
  const NarrowPhaseResult invalid = ellipsoid_contact(good, bad);
  EXPECT_EQ(invalid.status, NarrowPhaseStatus::failed);
  expect_finite(invalid);
  // Concentric bodies: no meaningful common normal (the overlap exceeds the reach).
  const NarrowPhaseResult concentric = ellipsoid_contact(good, Ellipsoid(Eigen::Vector3d(2, 1, 1)));
  EXPECT_NE(concentric.status, NarrowPhaseStatus::contact);
  expect_finite(concentric);
  // A garbage warm start falls back to the cold path.
  NarrowPhaseWarmStart garbage;
  garbage.valid = true;
  garbage.normal = {NAN, 0.0, 0.0};
  const Ellipsoid partner(Eigen::Vector3d(1, 1, 1), {Eigen::Vector3d(1.9, 0, 0), Eigen::Quaterniond::Identity()});
  const NarrowPhaseResult recovered = ellipsoid_contact(good, partner, &garbage);
  ASSERT_EQ(recovered.status, NarrowPhaseStatus::contact);
  EXPECT_NEAR(recovered.geometry.overlap, 0.1, 1e-14);
  garbage.normal = {-1.0, 0.0, 0.0};  // pointing from J to I: the far side
  const NarrowPhaseResult flipped = ellipsoid_contact(good, partner, &garbage);
  ASSERT_EQ(flipped.status, NarrowPhaseStatus::contact);
  EXPECT_NEAR(flipped.geometry.overlap, 0.1, 1e-14);
}

TEST(ContactFunction, SpheresHaveTheClosedForm) {
  // F* = |r|² / (R_I + R_J)² for spheres, at λ* = R_I / (R_I + R_J).
  const Ellipsoid i(Eigen::Vector3d::Constant(1.0));
  const Ellipsoid j(Eigen::Vector3d::Constant(2.0), {Eigen::Vector3d(0, 2.5, 0), Eigen::Quaterniond::Identity()});
  const ContactFunctionResult f = perram_wertheim(i, j, false);
  EXPECT_TRUE(f.converged);
  EXPECT_NEAR(f.value, 2.5 * 2.5 / 9.0, 1e-14);
  EXPECT_NEAR(f.lambda, 1.0 / 3.0, 1e-10);
  EXPECT_LT((f.normal - Eigen::Vector3d::UnitY()).norm(), 1e-14);
  const Ellipsoid far(Eigen::Vector3d::Constant(2.0), {Eigen::Vector3d(0, 3.5, 0), Eigen::Quaterniond::Identity()});
  EXPECT_TRUE(perram_wertheim(i, far).separated);
}

}  // namespace
}  // namespace ellc
