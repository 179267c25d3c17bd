// Acceptance (issue 3, item 4): the paper's tip-to-tip geometry through the general path
// (posed ellipsoids → narrow phase → normal_contact) gives the numbers of the special case that
// `ellc curve` uses (tip_contact → make_contact_constants → evaluate_contact) to 1e-12.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "ellc/geometry/narrow_phase.hpp"
#include "ellc/contact/normal_contact.hpp"
#include "ellc/geometry/tip_contact.hpp"
#include "support/geometry_support.hpp"
#include "support/nmc.hpp"

namespace ellc {
namespace {

constexpr double kTolerance = 1e-12;
constexpr double kDegree = std::numbers::pi / 180.0;

using test::kNmc;

Eigen::Vector3d from_aspect(const Eigen::Vector3d& aspect, double mean) { return aspect * (mean / std::cbrt(aspect.prod())); }

struct TipCase {
  Eigen::Vector3d axes_i;
  Eigen::Vector3d axes_j;
  double twist_i;
  double twist_j;
};

void expect_same_constants(const ContactConstants& general, const ContactConstants& special) {
  auto same = [](double a, double b, const char* name) {
    EXPECT_LE(test::relative_difference(a, b), kTolerance) << name << ": " << a << " vs " << b;
  };
  same(general.effective_modulus, special.effective_modulus, "E_e");
  same(general.yield_stress, special.yield_stress, "Y");
  same(general.equivalent_radius, special.equivalent_radius, "R_e");
  same(general.eccentricity_sq, special.eccentricity_sq, "e^2");
  same(general.f1, special.f1, "f1");
  same(general.f2, special.f2, "f2");
  same(general.contact_radius_sq_per_overlap, special.contact_radius_sq_per_overlap, "c_c^2/delta");
  same(general.hertz_coefficient, special.hertz_coefficient, "hertz coefficient");
  same(general.yield_pressure, special.yield_pressure, "p_Y");
  same(general.yield_contact_radius, special.yield_contact_radius, "c_Y");
  same(general.yield_overlap, special.yield_overlap, "delta_Y");
  same(general.yield_force, special.yield_force, "F_pY");
  same(general.lambda_max, special.lambda_max, "lambda_max");
  same(general.epsilon_max, special.epsilon_max, "epsilon_max");
  same(general.plastic_limit_overlap, special.plastic_limit_overlap, "delta_max");
}

// Load to 4.5 % of r̂^{I,J}, unload, reload to 10 %, unload (paper case 1 protocol).
std::vector<double> protocol(double mean_radius_sum) {
  std::vector<double> path;
  const double waypoints[] = {0.0, 0.045, 0.0, 0.10, 0.0};
  for (int segment = 0; segment + 1 < 5; ++segment)
    for (int k = 1; k <= 40; ++k)
      path.push_back(mean_radius_sum * (waypoints[segment] + (waypoints[segment + 1] - waypoints[segment]) * k / 40.0));
  return path;
}

void check_case(const TipCase& tip, HertzMode mode, const Eigen::Quaterniond& world_rotation,
                const Eigen::Vector3d& world_offset) {
  const ContactMaterial material = mix(kNmc, kNmc);
  const LawParameters law;
  const double mean_radius_sum = mean_radius(tip.axes_i) + mean_radius(tip.axes_j);
  const TipContact special_geometry = tip_contact({tip.axes_i, tip.twist_i}, {tip.axes_j, tip.twist_j});
  const ContactConstants special = make_contact_constants(material, special_geometry.body_i, special_geometry.body_j,
                                                          special_geometry.alpha, mean_radius_sum, mode, law);
  const Eigen::Quaterniond twist_i(Eigen::AngleAxisd(tip.twist_i, Eigen::Vector3d::UnitX()));
  const Eigen::Quaterniond twist_j(Eigen::AngleAxisd(tip.twist_j, Eigen::Vector3d::UnitX()));
  const Ellipsoid body_i(tip.axes_i, {world_offset, world_rotation * twist_i});
  const Eigen::Vector3d axis = world_rotation * Eigen::Vector3d::UnitX();

  double general_history = 0.0;
  double special_history = 0.0;
  double peak_force = 0.0;
  NarrowPhaseWarmStart warm;
  for (const double overlap : protocol(mean_radius_sum)) {
    const double separation = tip.axes_i.x() + tip.axes_j.x() - overlap;
    const Ellipsoid body_j(tip.axes_j, {world_offset + separation * axis, world_rotation * twist_j});
    const NarrowPhaseResult result = ellipsoid_contact(body_i, body_j, warm.valid ? &warm : nullptr);
    const double history_before = special_history;
    const LawResult reference = evaluate_contact(special, overlap, history_before);
    special_history = reference.max_overlap;
    if (overlap == 0.0) {  // touching: the general path sees no contact, the law no force
      EXPECT_NE(result.status, NarrowPhaseStatus::failed);
      EXPECT_EQ(reference.force, 0.0);
      continue;
    }
    ASSERT_EQ(result.status, NarrowPhaseStatus::contact) << "overlap " << overlap;
    warm = result.warm_start;
    // The measured overlap is the nominal one up to the rounding of the centre position.
    EXPECT_NEAR(result.geometry.overlap, overlap, 8e-16 * separation);
    EXPECT_LT((result.geometry.normal - axis).norm(), 1e-14);

    const NormalContact general =
        normal_contact(result.geometry, material, mean_radius_sum, mode, law, general_history);
    general_history = general.law.max_overlap;
    expect_same_constants(general.constants, special);
    // Forces. Near the end of an unloading F ∝ (δ − δ_p)^{3/2} with δ_p = δ_*(1 − R_e/R_e,p) a
    // difference of nearly equal numbers, so a 1-ulp change of any input moves F by far more
    // than 1 ulp relative; the curve is compared on its own scale (its peak force so far).
    peak_force = std::max(peak_force, reference.force);
    const LawResult at_measured = evaluate_contact(special, result.geometry.overlap, history_before);
    EXPECT_LE(std::abs(general.law.force - at_measured.force), kTolerance * std::max(at_measured.force, peak_force));
    if (overlap > 0.01 * mean_radius_sum) {  // δ itself is exact only to the rounding of the centre distance
      EXPECT_LE(std::abs(general.law.force - reference.force), kTolerance * std::max(reference.force, peak_force))
          << "overlap " << overlap << " regime " << regime_name(reference.regime);
    }
    // The regime too, except where the nominal δ sits on δ_* itself (reloading back to the
    // previous maximum): there the measured δ may land a rounding error on either side, and
    // loading and unloading give the same force.
    if (std::abs(overlap - history_before) > 1e-12 * overlap) {
      EXPECT_EQ(general.law.regime, reference.regime);
    }
    EXPECT_LT((general.force_on_j - general.law.force * axis).norm(), 1e-14 * (1.0 + general.law.force));
  }
}

std::vector<TipCase> paper_cases() {
  const double r1 = 4.675;
  const double r2 = 10.0;
  const Eigen::Vector3d case1_i = from_aspect({1.0, 1.25, 1.5}, r1);
  const Eigen::Vector3d case1_j = from_aspect({1.0, 0.5, 0.8}, r1);
  const Eigen::Vector3d case2_i = from_aspect({1.0, 1.0, 0.8}, r2);
  const Eigen::Vector3d case2_j = from_aspect({1.0, 1.25, 1.25}, r2);  // a spheroid: umbilic tip
  std::vector<TipCase> cases;
  for (const auto& [twist_i, twist_j] : std::vector<std::pair<double, double>>{
           {0.0, 0.0}, {30.0, 0.0}, {0.0, 75.0}, {45.0, -20.0}, {90.0, 0.0}, {137.0, 12.5}}) {
    cases.push_back({case1_i, case1_j, twist_i * kDegree, twist_j * kDegree});
    cases.push_back({case2_i, case2_j, twist_i * kDegree, twist_j * kDegree});
    cases.push_back({case1_j, case2_i, twist_i * kDegree, twist_j * kDegree});
  }
  return cases;
}

TEST(TipEquivalence, AlignedAndTwistedMatchTheSpecialCase) {
  for (const TipCase& tip : paper_cases())
    for (const HertzMode mode : {HertzMode::hale, HertzMode::exact}) {
      SCOPED_TRACE(::testing::Message() << "twists " << tip.twist_i / kDegree << ", " << tip.twist_j / kDegree
                                        << (mode == HertzMode::exact ? " exact" : " hale"));
      check_case(tip, mode, Eigen::Quaterniond::Identity(), Eigen::Vector3d::Zero());
    }
}

TEST(TipEquivalence, MatchesTheSpecialCaseInAnyWorldPose) {
  test::Rng rng(20);
  for (const TipCase& tip : paper_cases()) {
    const Eigen::Quaterniond rotation = test::random_orientation(rng);
    const Eigen::Vector3d offset(test::uniform(rng, -50, 50), test::uniform(rng, -50, 50), test::uniform(rng, -50, 50));
    SCOPED_TRACE(::testing::Message() << "twists " << tip.twist_i / kDegree << ", " << tip.twist_j / kDegree);
    check_case(tip, HertzMode::hale, rotation, offset);
  }
}

TEST(TipEquivalence, AlphaIsTheTwistDifference) {
  const Eigen::Vector3d axes_i(4.0, 5.0, 6.0);
  const Eigen::Vector3d axes_j(4.0, 2.0, 3.2);
  for (const double twist : {0.0, 10.0, 45.0, 80.0, 90.0}) {
    const Ellipsoid i(axes_i, {Eigen::Vector3d::Zero(), Eigen::Quaterniond(Eigen::AngleAxisd(twist * kDegree, Eigen::Vector3d::UnitX()))});
    const Ellipsoid j(axes_j, {Eigen::Vector3d(7.9, 0, 0), Eigen::Quaterniond::Identity()});
    const NarrowPhaseResult result = ellipsoid_contact(i, j);
    ASSERT_EQ(result.status, NarrowPhaseStatus::contact);
    EXPECT_NEAR(result.geometry.alpha, twist * kDegree, 1e-14);
    EXPECT_DOUBLE_EQ(result.geometry.curvature_i.kappa_1, 4.0 / 25.0 > 4.0 / 36.0 ? 4.0 / 25.0 : 4.0 / 36.0);
    EXPECT_DOUBLE_EQ(result.geometry.curvature_j.kappa_1, 4.0 / 4.0);
  }
}

}  // namespace
}  // namespace ellc
