// The LAMMPS-free parts of pair_style ellipsoid/bk: pair_coeff parsing and mixing, and the
// adapter to the shared contact model (normal law, damping, friction, history record).

#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

#include "ellc/contact/pair_contact.hpp"
#include "ellc/engine/rigid_body.hpp"
#include "ellc/law/contact_constants.hpp"
#include "pair_adapter.hpp"
#include "pair_coefficients.hpp"
#include "support/nmc.hpp"

namespace ellc_lammps {
namespace {

using ellc::test::kNmc;
using ellc::test::nmc_pair_coeff;

TEST(PairCoefficients, ParsesPositionalValuesAndKeywords) {
  const auto parsed = parse_coefficients(
      nmc_pair_coeff({"friction", "0.3", "damping", "0.1", "lambda", "1", "-4", "2.5", "exponent", "2"}));
  ASSERT_EQ(parsed.error, "");
  const auto& c = parsed.coefficients;
  EXPECT_EQ(c.material.youngs_modulus, kNmc.youngs_modulus);
  EXPECT_EQ(c.material.poisson_ratio, kNmc.poisson_ratio);
  EXPECT_EQ(c.material.yield_stress, kNmc.yield_stress);
  EXPECT_EQ(c.model.friction, 0.3);
  EXPECT_EQ(c.model.normal_damping, 0.1);
  EXPECT_EQ(c.model.law.fit.lambda_amplitude, 1.0);
  EXPECT_EQ(c.model.law.fit.lambda_rate, -4.0);
  EXPECT_EQ(c.model.law.fit.lambda_offset, 2.5);
  EXPECT_EQ(c.model.law.fit.transition_exponent, 2.0);
  EXPECT_EQ(c.model.law.fit.epsilon_amplitude, ellc::TransitionFit{}.epsilon_amplitude);  // default kept
}

TEST(PairCoefficients, RejectsBadInputWithTheFieldName) {
  EXPECT_NE(parse_coefficients({"0", "0.25", "7900"}).error.find("youngs_modulus = 0"), std::string::npos);
  EXPECT_NE(parse_coefficients({"-1", "0.25", "7900"}).error.find("youngs_modulus"), std::string::npos);
  EXPECT_NE(parse_coefficients({"1", "0.5", "7900"}).error.find("poisson_ratio = 0.5"), std::string::npos);
  EXPECT_NE(parse_coefficients({"1", "-1", "7900"}).error.find("poisson_ratio"), std::string::npos);
  EXPECT_NE(parse_coefficients({"1", "0.2", "0"}).error.find("yield_stress"), std::string::npos);
  EXPECT_NE(parse_coefficients({"1", "0.2"}).error.find("expected pair_coeff"), std::string::npos);
  EXPECT_NE(parse_coefficients({"1", "0.2", "x"}).error.find("not a number"), std::string::npos);
  EXPECT_NE(parse_coefficients({"1", "0.2", "3", "colour", "1"}).error.find("unknown keyword"), std::string::npos);
  EXPECT_NE(parse_coefficients({"1", "0.2", "3", "lambda", "1", "2"}).error.find("needs 3"), std::string::npos);
  EXPECT_NE(parse_coefficients({"1", "0.2", "3", "friction", "-0.1"}).error.find("friction"), std::string::npos);
}

TEST(PairCoefficients, MixesMaterialsByEquationThreeAndTheSofterYield) {
  const auto steel = parse_coefficients({"210000", "0.3", "900", "friction", "0.4"}).coefficients;
  const auto nmc = parse_coefficients(nmc_pair_coeff({"friction", "0.1"})).coefficients;
  std::string error;
  const ellc::InteractionContext mixed = mixed_pair(steel, nmc, error);
  EXPECT_EQ(error, "");
  const double nmc_plane_strain = kNmc.youngs_modulus / (1 - kNmc.poisson_ratio * kNmc.poisson_ratio);
  const double expected = 1.0 / ((1 - 0.09) / 210000.0 + 1.0 / nmc_plane_strain);
  EXPECT_NEAR(mixed.material.effective_modulus, expected, 1e-9 * expected);
  EXPECT_EQ(mixed.material.yield_stress, 900.0);
  EXPECT_NEAR(mixed.model.friction, 0.2, 1e-15);
  const ellc::InteractionContext same = explicit_pair(nmc);
  EXPECT_NEAR(same.material.effective_modulus, nmc_plane_strain / 2, 1e-9);
}

TEST(PairCoefficients, RefusesToMixDifferentLawParameters) {
  const auto one = parse_coefficients({"1", "0.2", "3"}).coefficients;
  const auto two = parse_coefficients({"1", "0.2", "3", "exponent", "2"}).coefficients;
  std::string error;
  (void)mixed_pair(one, two, error);
  EXPECT_NE(error.find("own pair_coeff"), std::string::npos);
}

TEST(PairCoefficients, SerializationRoundTrips) {
  const auto c = parse_coefficients(nmc_pair_coeff({"friction", "0.3", "tangential_stiffness", "0.8", "epsilon", "8",
                                                    "-6", "1.2", "yield_factor", "1.5"}))
                     .coefficients;
  const auto back = TypeCoefficients::deserialize(c.serialize());
  EXPECT_EQ(back.serialize(), c.serialize());
}

// Two equal NMC spheres of radius 5 along x: R_e = 2.5, Hertz until δ_Y.
struct SpherePair : ::testing::Test {
  BodyState a, b;
  ellc::InteractionContext coefficients;
  std::vector<double> history = std::vector<double>(static_cast<std::size_t>(kHistoryDoubles), 0.0);
  SpherePair() {
    a.semi_axes = b.semi_axes = Eigen::Vector3d::Constant(5.0);
    a.mass = b.mass = 2.0;
    coefficients = explicit_pair(parse_coefficients(nmc_pair_coeff()).coefficients);
  }
  PairEvaluation at_overlap(double overlap) {
    b.position = {10.0 - overlap, 0.0, 0.0};
    return evaluate_pair(a, b, coefficients, 1e-3, history.data());
  }
};

TEST_F(SpherePair, NormalForceIsTheLawAndPointsFromAToB) {
  const auto result = at_overlap(0.01);
  ASSERT_TRUE(result.touching);
  const auto constants = ellc::make_contact_constants(coefficients.material, {0.2, 0.2}, {0.2, 0.2}, 0.0, 10.0,
                                                      ellc::HertzMode::hale, coefficients.model.law);
  const double expected = ellc::evaluate_contact(constants, result.overlap, 0.0).force;
  EXPECT_NEAR(result.force_on_b.x(), expected, 1e-12 * expected);
  EXPECT_NEAR(result.force_on_b.y(), 0.0, 1e-12 * expected);
  EXPECT_NEAR(result.torque_on_a.norm() + result.torque_on_b.norm(), 0.0, 1e-9 * expected);
  EXPECT_DOUBLE_EQ(ellc::ContactHistory::read_from(history.data()).max_overlap, result.overlap);
}

TEST_F(SpherePair, KeepsTheLargestOverlapAndForgetsItOnSeparation) {
  (void)at_overlap(1.0);
  const double deepest = ellc::ContactHistory::read_from(history.data()).max_overlap;
  const auto unloading = at_overlap(0.9);
  EXPECT_EQ(ellc::ContactHistory::read_from(history.data()).max_overlap, deepest);
  EXPECT_EQ(unloading.law.regime, ellc::Regime::unloading);
  const auto apart = at_overlap(-0.1);
  EXPECT_FALSE(apart.touching);
  // δ_* and the spring are gone; only the separating axis stays, as the narrow phase's warm start.
  const ellc::ContactHistory record = ellc::ContactHistory::read_from(history.data());
  EXPECT_EQ(record.max_overlap, 0.0);
  EXPECT_EQ(record.spring().norm(), 0.0);
  EXPECT_TRUE(apart.keep_warm_start);
  EXPECT_NEAR(record.warm_normal[0], 1.0, 1e-12);  // the line of centres, a to b
}

TEST_F(SpherePair, FrictionIsCappedByCoulombAndDampingOpposesApproach) {
  coefficients.model.friction = 0.2;
  coefficients.model.normal_damping = 0.3;
  b.velocity = {-1.0, 50.0, 0.0};  // approaching and sliding fast along y
  const auto result = at_overlap(0.05);
  ASSERT_TRUE(result.touching);
  EXPECT_GT(result.normal_force, result.law.force);  // damping adds while approaching
  const double tangential = std::hypot(result.force_on_b.y(), result.force_on_b.z());
  EXPECT_NEAR(tangential, 0.2 * result.normal_force, 1e-12 * result.normal_force);
  EXPECT_LT(result.force_on_b.y(), 0.0);  // opposes b's sliding
  // The friction force at the contact point (midway) turns both spheres the same way.
  EXPECT_GT(result.torque_on_b.norm(), 0.0);
  EXPECT_TRUE(result.torque_on_a.isApprox(result.torque_on_b, 1e-12));
}

// Two ellipsoids in general poses, overlapping, moving and spinning.
std::pair<BodyState, BodyState> general_pose_pair() {
  BodyState a, b;
  a.semi_axes = {6.0, 5.0, 4.2};
  b.semi_axes = {3.0, 5.5, 4.0};
  a.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized()));
  b.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(-1.1, Eigen::Vector3d(-2, 1, 0.5).normalized()));
  a.position = {0.3, -0.2, 0.1};
  b.position = {8.0, 2.0, -1.5};
  a.velocity = {0.5, 0.1, 0.0};
  b.angular_velocity = {0.0, 3.0, -1.0};
  a.mass = 3.0;
  b.mass = 1.5;
  return {a, b};
}

TEST(EllipsoidPair, ConservesMomentumAndAngularMomentumInAGeneralPose) {
  const auto [a, b] = general_pose_pair();
  const ellc::InteractionContext c =
      explicit_pair(parse_coefficients(nmc_pair_coeff({"friction", "0.3", "damping", "0.2"})).coefficients);
  std::vector<double> history(static_cast<std::size_t>(kHistoryDoubles), 0.0);
  const PairEvaluation result = evaluate_pair(a, b, c, 1e-3, history.data());
  ASSERT_TRUE(result.touching);
  EXPECT_GT(result.overlap, 0.0);
  EXPECT_GT(result.normal.dot(b.position - a.position), 0.0);  // normal points from a to b
  // Equal and opposite forces at one point: the torques about the centres balance the moment.
  const Eigen::Vector3d moment =
      result.torque_on_a + result.torque_on_b + (b.position - a.position).cross(result.force_on_b);
  EXPECT_LT(moment.norm(), 1e-9 * result.force_on_b.norm() * 10.0);
  // The warm start is kept for the next step, and a second evaluation from it agrees.
  EXPECT_EQ(ellc::ContactHistory::read_from(history.data()).warm_valid, 1.0);
  ellc::ContactHistory warm_record = ellc::ContactHistory::read_from(history.data());
  warm_record.tangential_spring = {};
  std::vector<double> again(static_cast<std::size_t>(kHistoryDoubles), 0.0);
  warm_record.write_to(again.data());
  std::vector<double> cold(static_cast<std::size_t>(kHistoryDoubles), 0.0);
  const PairEvaluation warm_result = evaluate_pair(a, b, c, 1e-3, again.data());
  const PairEvaluation cold_result = evaluate_pair(a, b, c, 1e-3, cold.data());
  EXPECT_NEAR(warm_result.overlap, cold_result.overlap, 1e-12);
}

TEST(PairCoefficients, SharedContactVocabularyAndTheOlderNames) {
  const auto c = parse_coefficients({"142000", "0.25", "7900", "damping", "0.2", "tangential_damping", "0.1",
                                     "damping_model", "hertz_tangent", "normal", "hertz"})
                     .coefficients;
  EXPECT_EQ(c.model.normal_damping, 0.2);  // `damping` is normal_damping's older name
  EXPECT_EQ(c.model.tangential_damping, 0.1);
  EXPECT_EQ(c.model.damping, ellc::DampingModel::hertz_tangent);
  EXPECT_EQ(c.model.normal, ellc::NormalModel::hertz);
  EXPECT_EQ(c.model.tangential, ellc::TangentialModel::mindlin);  // the engine's default
  const auto ratio = parse_coefficients({"142000", "0.25", "7900", "tangential_stiffness", "0.8"}).coefficients;
  EXPECT_EQ(ratio.model.tangential, ellc::TangentialModel::ratio);  // old inputs keep their meaning
  EXPECT_NE(parse_coefficients({"1", "0.2", "3", "normal", "thornton"})
                .error.find("normal = thornton: expected "
                            "becker_kamlah or hertz"),
            std::string::npos);
  EXPECT_NE(parse_coefficients({"1", "0.2", "3", "damping_ratio", "1.5"}).error.find("damping_ratio = 1.5"),
            std::string::npos);
  // k_t/k_n = 1e300 once ran and gave a NaN kinetic energy: refused by name.
  const std::string stiff = parse_coefficients({"1", "0.2", "3", "tangential_stiffness", "1e300"}).error;
  EXPECT_NE(stiff.find("tangential_stiffness = 1e300"), std::string::npos) << stiff;  // as typed
  EXPECT_NE(stiff.find("[0, 1.5]"), std::string::npos) << stiff;
  const auto a = parse_coefficients({"1", "0.2", "3"}).coefficients;
  const auto b = parse_coefficients({"1", "0.2", "3", "tangential_model", "ratio"}).coefficients;
  std::string error;
  (void)mixed_pair(a, b, error);
  EXPECT_NE(error.find("different sub-models"), std::string::npos);
}

// pair_style ellipsoid/bk runs the built-in engine's contact model: the same bodies, history and
// parameters give the same forces, bit for bit, through the adapter and through the shared code.
TEST(OneContactModel, AdapterGivesExactlyTheSharedPairForces) {
  const auto [a, b] = general_pose_pair();
  const ellc::InteractionContext context = explicit_pair(
      parse_coefficients({"142000", "0.25", "7900", "friction", "0.3", "damping_ratio", "0.2"}).coefficients);
  std::vector<double> stored(static_cast<std::size_t>(kHistoryDoubles), 0.0);
  PairEvaluation through_adapter;
  for (int step = 0; step < 3; ++step) through_adapter = evaluate_pair(a, b, context, 1e-3, stored.data());

  ellc::ContactHistory history;
  ellc::PairForces shared;
  const ellc::Ellipsoid shape_a(a.semi_axes, {a.position, a.orientation});
  const ellc::Ellipsoid shape_b(b.semi_axes, {b.position, b.orientation});
  for (int step = 0; step < 3; ++step) {
    ellc::ContactCache cache;
    const ellc::PairSolution solution = ellc::solve_pair(
        {a.semi_axes, a.position, a.orientation, shape_a.mean_radius(), &shape_a},
        {b.semi_axes, b.position, b.orientation, shape_b.mean_radius(), &shape_b}, false, history, cache, context);
    ASSERT_EQ(solution.status, ellc::PairStatus::contact);
    shared = ellc::pair_forces(solution, a.position, {a.velocity, a.angular_velocity, a.mass}, b.position,
                               {b.velocity, b.angular_velocity, b.mass}, context, 1e-3, history);
  }
  EXPECT_EQ(through_adapter.force_on_b, shared.contact.on_j);
  EXPECT_EQ(through_adapter.torque_on_a, shared.torque_on_i);
  EXPECT_EQ(through_adapter.torque_on_b, shared.torque_on_j);
  double flat[ellc::ContactHistory::kDoubles];
  history.write_to(flat);
  for (std::size_t k = 0; k < ellc::ContactHistory::kDoubles; ++k) EXPECT_EQ(stored[k], flat[k]) << k;
}

TEST(AngularVelocity, IsMomentumOverInertiaForASphereAndRotatesWithTheBody) {
  const Eigen::Vector3d momentum{1.0, -2.0, 0.5};
  using ellc::engine::angular_velocity_from_momentum;
  using ellc::engine::solid_ellipsoid_inertia;
  const Eigen::Vector3d sphere =
      angular_velocity_from_momentum(momentum, Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ())),
                                     solid_ellipsoid_inertia(5.0, Eigen::Vector3d::Constant(2.0)));
  EXPECT_TRUE(sphere.isApprox(momentum / (0.4 * 5.0 * 4.0), 1e-14));
  // A rod spinning about its long body axis x, turned so that x points along space y.
  const Eigen::Quaterniond turned(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()));
  const Eigen::Vector3d spin =
      angular_velocity_from_momentum({0.0, 1.0, 0.0}, turned, solid_ellipsoid_inertia(1.0, {3.0, 1.0, 1.0}));
  EXPECT_NEAR(spin.y(), 1.0 / (0.2 * 2.0), 1e-12);
  EXPECT_NEAR(spin.x(), 0.0, 1e-12);
}

}  // namespace
}  // namespace ellc_lammps
