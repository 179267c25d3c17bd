// The tangential history spring with Coulomb's limit (src/ellc/contact/tangential_spring.hpp).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>

#include "ellc/contact/tangential_spring.hpp"

namespace {
using namespace ellc;
using Eigen::Vector3d;

constexpr double kDt = 1e-3;

// A random state that sticks or slides depending on the draw: normal, spring, velocity, F_n.
struct State {
  Vector3d spring;
  Vector3d normal;
  Vector3d velocity;
  double normal_force;
  TangentialCoefficients coefficients;
};

State random_state(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  const auto vector = [&] { return Vector3d(uniform(rng), uniform(rng), uniform(rng)); };
  State s;
  s.normal = vector().normalized();
  s.spring = 1e-4 * vector();
  s.velocity = 0.1 * vector();
  s.normal_force = 5.0 * (1.0 + uniform(rng));
  s.coefficients = {1e4 * (1.5 + uniform(rng)), 2.0 * (1.0 + uniform(rng)), 0.3 * (1.0 + uniform(rng))};
  return s;
}

TangentialResponse respond(const State& s) {
  return tangential_response(s.spring, s.normal, s.velocity, kDt, s.normal_force, s.coefficients);
}

Vector3d tangential_part(const Vector3d& v, const Vector3d& n) { return v - v.dot(n) * n; }

TEST(TangentialSpring, ForceNeverExceedsCoulomb) {
  std::mt19937_64 rng(20260101);
  int sliding = 0;
  for (int k = 0; k < 2000; ++k) {
    const State s = random_state(rng);
    const TangentialResponse r = respond(s);
    const double limit = s.coefficients.friction * s.normal_force;
    EXPECT_LE(r.force.norm(), limit * (1.0 + 1e-14));
    EXPECT_NEAR(r.force.dot(s.normal), 0.0, 1e-12 * limit);  // purely tangential
    EXPECT_NEAR(r.spring.dot(s.normal), 0.0, 1e-12 * r.spring.norm() + 1e-300);
    sliding += r.sliding ? 1 : 0;
  }
  EXPECT_GT(sliding, 100);  // the sample covers both regimes
  EXPECT_LT(sliding, 1900);
}

TEST(TangentialSpring, StickForceIsSpringPlusDashpot) {
  const Vector3d n = Vector3d(1.0, 2.0, -2.0).normalized();
  const Vector3d spring = 1e-4 * Vector3d(2.0, 0.0, 1.0);  // tangential: (2, 0, 1)·(1, 2, −2) = 0
  const Vector3d v(0.3, -0.2, 0.5);
  const TangentialCoefficients c{2e3, 1.5, 0.5};
  const TangentialResponse r = tangential_response(spring, n, v, kDt, 100.0, c);
  ASSERT_FALSE(r.sliding);
  const Vector3d v_t = tangential_part(v, n);
  const Vector3d expected_spring = spring + v_t * kDt;  // ξ += v_t dt
  EXPECT_LT((r.spring - expected_spring).norm(), 1e-15 * expected_spring.norm());
  const Vector3d expected_force = -c.stiffness * expected_spring - c.damping * v_t;
  EXPECT_LT((r.force - expected_force).norm(), 1e-14 * expected_force.norm());
}

TEST(TangentialSpring, OnlyTheTangentialVelocityLoadsTheSpring) {
  std::mt19937_64 rng(7);
  for (int k = 0; k < 100; ++k) {
    const State s = random_state(rng);
    State approaching = s;
    approaching.velocity += 3.0 * s.normal;
    const TangentialResponse a = respond(s);
    const TangentialResponse b = respond(approaching);
    EXPECT_LT((a.force - b.force).norm(), 1e-12 * (1.0 + a.force.norm()));
    EXPECT_LT((a.spring - b.spring).norm(), 1e-12 * (1e-4 + a.spring.norm()));
  }
}

TEST(TangentialSpring, SlipCapsAtCoulombAndResetsTheSpringToIt) {
  const Vector3d n = Vector3d::UnitZ();
  const Vector3d v(2.0, 1.0, 0.0);
  const TangentialCoefficients c{1e4, 3.0, 0.4};
  const double normal_force = 10.0;
  const double limit = c.friction * normal_force;
  const TangentialResponse r = tangential_response(Vector3d(1e-3, 0.0, 0.0), n, v, kDt, normal_force, c);
  ASSERT_TRUE(r.sliding);
  EXPECT_NEAR(r.force.norm(), limit, 1e-14 * limit);
  // The reset spring gives exactly the capped force: −k_t ξ − c_t v_t = F_t.
  EXPECT_LT((-c.stiffness * r.spring - c.damping * v - r.force).norm(), 1e-14 * limit);
  // Sliding on without damping: the force stays on the limit, opposite to the motion.
  const TangentialCoefficients undamped{c.stiffness, 0.0, c.friction};
  TangentialResponse step = tangential_response(Vector3d::Zero(), n, v, 1.0, normal_force, undamped);
  for (int k = 0; k < 5; ++k) {
    step = tangential_response(step.spring, n, v, kDt, normal_force, undamped);
    ASSERT_TRUE(step.sliding);
    EXPECT_NEAR(step.force.norm(), limit, 1e-14 * limit);
    EXPECT_NEAR(step.force.normalized().dot(-v.normalized()), 1.0, 1e-14);
    EXPECT_NEAR(step.spring.norm(), limit / c.stiffness, 1e-14 * limit / c.stiffness);
  }
}

TEST(TangentialSpring, NoNormalForceNoTangentialForce) {
  const TangentialCoefficients c{1e4, 0.0, 0.5};
  const TangentialResponse r =
      tangential_response(Vector3d(1e-3, 2e-3, 0.0), Vector3d::UnitZ(), Vector3d(1.0, 0.0, 0.0), kDt, 0.0, c);
  EXPECT_TRUE(r.sliding);
  EXPECT_EQ(r.force.norm(), 0.0);
  EXPECT_EQ(r.spring.norm(), 0.0);  // nothing stored while the contact carries no load
}

TEST(TangentialSpring, ZeroFrictionOrStiffnessGivesNoForceAndNoMemory) {
  const Vector3d spring(1e-3, -2e-3, 0.0);
  const Vector3d v(1.0, 1.0, 0.0);
  const TangentialCoefficients no_friction{1e4, 2.0, 0.0};
  const TangentialCoefficients no_spring{0.0, 2.0, 0.3};
  for (const TangentialCoefficients& c : {no_friction, no_spring}) {
    const TangentialResponse r = tangential_response(spring, Vector3d::UnitZ(), v, kDt, 50.0, c);
    EXPECT_EQ(r.force, Vector3d::Zero());
    EXPECT_EQ(r.spring, Vector3d::Zero());
    EXPECT_FALSE(r.sliding);
  }
}

TEST(TangentialSpring, TurningTheNormalKeepsTheSpringLengthAndMakesItTangential) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (int k = 0; k < 500; ++k) {
    const Vector3d spring(uniform(rng), uniform(rng), uniform(rng));
    const Vector3d n = Vector3d(uniform(rng), uniform(rng), uniform(rng)).normalized();
    const Vector3d carried = carry_to_tangent_plane(spring, n);
    EXPECT_NEAR(carried.norm(), spring.norm(), 1e-14 * spring.norm());
    EXPECT_NEAR(carried.dot(n), 0.0, 1e-14 * spring.norm());
    // It stays in the plane of ξ and n (turned, not twisted) and on ξ's side.
    EXPECT_NEAR(carried.dot(spring.cross(n)), 0.0, 1e-14 * spring.squaredNorm());
    EXPECT_GE(carried.dot(spring), 0.0);
  }
  // Already tangential: unchanged. Along the normal: no tangential direction, so no spring.
  const Vector3d tangential(0.3, -0.4, 0.0);
  EXPECT_LT((carry_to_tangent_plane(tangential, Vector3d::UnitZ()) - tangential).norm(), 1e-16);
  EXPECT_EQ(carry_to_tangent_plane(Vector3d(0.0, 0.0, 2e-3), Vector3d::UnitZ()), Vector3d::Zero());
  EXPECT_EQ(carry_to_tangent_plane(Vector3d::Zero(), Vector3d::UnitX()), Vector3d::Zero());
  // Through the step: ξ along y was tangential to z; the normal turns by 0.5 rad about x. At rest
  // (v = 0) the stuck contact keeps the full spring force, where a plain projection would lose
  // the factor cos 0.5.
  const TangentialCoefficients c{1e3, 0.0, 1.0};
  const Vector3d turned_normal(0.0, std::sin(0.5), std::cos(0.5));
  const TangentialResponse r =
      tangential_response(Vector3d(0.0, 1e-3, 0.0), turned_normal, Vector3d::Zero(), kDt, 10.0, c);
  ASSERT_FALSE(r.sliding);
  EXPECT_NEAR(r.force.norm(), 1e3 * 1e-3, 1e-15);
  EXPECT_NEAR(r.spring.dot(turned_normal), 0.0, 1e-18);
}

// Work done on J over a closed path of the contact point, c_t = 0: in stick the spring gives back
// what it stored; with slip the contact dissipates. It never creates energy.
double cycle(double normal_force, Vector3d& spring, bool& slid) {
  const TangentialCoefficients c{1e4, 0.0, 0.5};
  const Vector3d n = Vector3d::UnitZ();
  const Vector3d legs[] = {Vector3d(1.0, 0.0, 0.0), Vector3d(0.0, 1.0, 0.0), Vector3d(-1.0, 0.0, 0.0),
                           Vector3d(0.0, -1.0, 0.0)};
  double work = 0.0;
  spring.setZero();
  slid = false;
  for (const Vector3d& v : legs) {
    for (int k = 0; k < 100; ++k) {
      const TangentialResponse r = tangential_response(spring, n, v, kDt, normal_force, c);
      work += r.force.dot(v) * kDt;
      spring = r.spring;
      slid = slid || r.sliding;
    }
  }
  return work;
}

TEST(TangentialSpring, ClosedStickCycleReturnsTheSpringToZero) {
  Vector3d spring;
  bool slid = true;
  const double stick_work = cycle(1e4, spring, slid);  // μ F_n = 5000 > k_t |ξ| ≤ 1e4 · 0.1 √2
  ASSERT_FALSE(slid);
  EXPECT_LT(spring.norm(), 1e-15);
  // Backward-difference storage loses ½ k_t Σ|Δξ|² (= 2 here per cycle of 400 steps of 1e-3):
  // passive, and small against the ½ k_t |ξ|² = 100 stored at the corners.
  EXPECT_LE(stick_work, 0.0);
  EXPECT_NEAR(stick_work, -0.5 * 1e4 * 400 * kDt * kDt, 1e-9);

  const double slip_work = cycle(20.0, spring, slid);  // μ F_n = 10: slides on every leg
  ASSERT_TRUE(slid);
  EXPECT_GT(spring.norm(), 0.0);      // a slid contact keeps a set
  EXPECT_LT(slip_work, -10.0 * 0.2);  // dissipates at least μ F_n over half of the 0.4 travelled
}

// The contact model carries ξ once (contact_force.hpp: carry, then the rescale for a changed k_t)
// and hands the carried spring to tangential_response_on_plane: steps 2–4 of the same step.
TEST(TangentialSpring, TheResponseOnThePlaneIsTheStepAfterTheCarry) {
  std::mt19937_64 rng(5);
  for (int k = 0; k < 500; ++k) {
    const State s = random_state(rng);
    const TangentialResponse full = respond(s);
    const TangentialResponse on_plane = tangential_response_on_plane(
        carry_to_tangent_plane(s.spring, s.normal), s.normal, s.velocity, kDt, s.normal_force, s.coefficients);
    EXPECT_EQ(full.force, on_plane.force);
    EXPECT_EQ(full.spring, on_plane.spring);
    EXPECT_EQ(full.sliding, on_plane.sliding);
  }
  // A spring off the plane is taken as it is: the caller carries it, so a stuck contact at rest
  // under a turned normal keeps the spring's full force only through the carry.
  const TangentialCoefficients c{1e3, 0.0, 1.0};
  const Vector3d turned_normal(0.0, std::sin(0.5), std::cos(0.5));
  const Vector3d spring(0.0, 1e-3, 0.0);
  const TangentialResponse carried = tangential_response_on_plane(carry_to_tangent_plane(spring, turned_normal),
                                                                  turned_normal, Vector3d::Zero(), kDt, 10.0, c);
  EXPECT_NEAR(carried.force.norm(), 1e3 * 1e-3, 1e-15);
  EXPECT_NEAR(carried.force.dot(turned_normal), 0.0, 1e-15);
}

TEST(TangentialSpring, InvariantUnderARotationOfTheFrame) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (int k = 0; k < 300; ++k) {
    const State s = random_state(rng);
    const Eigen::Matrix3d rotation =
        Eigen::AngleAxisd(3.0 * uniform(rng), Vector3d(uniform(rng), uniform(rng), uniform(rng)).normalized())
            .toRotationMatrix();
    State turned = s;
    turned.spring = rotation * s.spring;
    turned.normal = rotation * s.normal;
    turned.velocity = rotation * s.velocity;
    const TangentialResponse a = respond(s);
    const TangentialResponse b = respond(turned);
    EXPECT_EQ(a.sliding, b.sliding);
    EXPECT_LT((rotation * a.force - b.force).norm(), 1e-12 * (1.0 + a.force.norm()));
    EXPECT_LT((rotation * a.spring - b.spring).norm(), 1e-12 * (1e-4 + a.spring.norm()));
  }
}

}  // namespace
