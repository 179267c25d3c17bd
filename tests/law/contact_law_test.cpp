// The Becker–Kamlah law: continuity, the unloading construction, reloading, symmetry, regimes.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "ellc/law/law_along_path.hpp"
#include "law_fixtures.hpp"

namespace {
using namespace ellc;
using ellc::testing::paper_case1;
using ellc::testing::paper_case2;

double relative_jump(double left, double right) { return std::abs(left - right) / std::abs(right); }

std::vector<ContactConstants> all_cases() {
  return {paper_case1(), paper_case2(), paper_case1(HertzMode::exact), paper_case2(HertzMode::exact)};
}

TEST(Law, PaperCase2GeometryAsInModelNotes) {
  const auto c = paper_case2();
  EXPECT_NEAR(c.equivalent_radius, 5.22, 0.01);  // docs/model.md §6
  EXPECT_NEAR(c.epsilon_max, 2.79, 0.01);
  EXPECT_NEAR(c.plastic_limit_overlap, c.epsilon_max * c.epsilon_max * c.yield_overlap, 1e-15);
}

TEST(Law, YieldPointIsConsistent) {
  for (const auto& c : all_cases()) {
    // F_pY = (2/3)π c_Y² p_Y equals Hertz at δ_Y, and p0(δ_Y) = p_Y (eq. 2).
    EXPECT_NEAR(c.hertz_coefficient * std::pow(c.yield_overlap, 1.5) / c.yield_force, 1.0, 1e-13);
    const auto contact = hertz_contact(hertz_shape_of(c), c.effective_modulus, c.yield_overlap);
    EXPECT_NEAR(contact.peak_pressure / c.yield_pressure, 1.0, 1e-13);
  }
}

TEST(Law, ForceIsContinuousAtTheElasticLimitAndAtDeltaMax) {
  for (const auto& c : all_cases()) {
    for (double boundary : {c.yield_overlap, c.plastic_limit_overlap}) {
      const double below = loading_force(c, boundary).force;
      const double above = loading_force(c, std::nextafter(boundary, 1e300)).force;
      EXPECT_LT(relative_jump(above, below), 1e-12) << boundary;
    }
    EXPECT_EQ(loading_force(c, c.yield_overlap).regime, Regime::elastic);
    EXPECT_EQ(loading_force(c, 1.0001 * c.yield_overlap).regime, Regime::elastic_plastic);
    EXPECT_EQ(loading_force(c, 1.0001 * c.plastic_limit_overlap).regime, Regime::fully_plastic);
  }
}

TEST(Law, LambdaRisesFromYieldToLambdaMax) {
  const auto c = paper_case1();
  const double c_y = c.yield_contact_radius;
  EXPECT_NEAR(transition_lambda(c, c_y), c.yield_pressure_factor, 1e-14);
  EXPECT_NEAR(transition_lambda(c, c.epsilon_max * c_y), c.lambda_max, 1e-14);
  double previous = 0.0;
  for (double radius = c_y; radius <= c.epsilon_max * c_y; radius += 0.01 * c_y) {
    const double lambda = transition_lambda(c, radius);
    EXPECT_GE(lambda, previous);
    previous = lambda;
  }
}

TEST(Law, ForceIsContinuousAtEveryTurningPoint) {
  for (const auto& c : all_cases()) {
    for (double factor : {0.5, 1.0, 1.5, 3.0, 7.0, 20.0}) {
      const double turn = factor * c.yield_overlap;
      const LawResult at_turn = evaluate_contact(c, turn, 0.0);
      const LawResult after = evaluate_contact(c, std::nextafter(turn, 0.0), at_turn.max_overlap);
      EXPECT_LT(relative_jump(after.force, at_turn.force), 1e-12) << "turn at " << factor << " delta_Y";
      EXPECT_EQ(after.max_overlap, turn);
    }
  }
}

TEST(Law, UnloadingStartsAtTheHistoryPointAndEndsAtThePlasticOverlap) {
  for (const auto& c : all_cases()) {
    for (double factor : {1.5, 5.0, 12.0}) {
      const double max_overlap = factor * c.yield_overlap;
      const UnloadingBranch branch = unloading_branch(c, max_overlap);
      EXPECT_NEAR(branch.unloading_coefficient * std::pow(max_overlap - branch.plastic_overlap, 1.5) /
                      loading_force(c, max_overlap).force,
                  1.0, 1e-12);
      EXPECT_GT(branch.plastic_overlap, 0.0);
      EXPECT_LT(branch.plastic_overlap, max_overlap);
      EXPECT_EQ(evaluate_contact(c, branch.plastic_overlap, max_overlap).force, 0.0);
      EXPECT_EQ(evaluate_contact(c, branch.plastic_overlap, max_overlap).regime, Regime::separated);
      EXPECT_GT(evaluate_contact(c, branch.plastic_overlap * (1 + 1e-9), max_overlap).force, 0.0);
      // R_e,pmax = β² R_e,p (eq. 48) and F_UL is Hertz with that radius (eq. 49).
      EXPECT_NEAR(branch.unloading_radius, branch.force_ratio * branch.force_ratio * branch.plastic_radius,
                  1e-12 * branch.unloading_radius);
    }
  }
}

// Paper case 2's protocol (δ_* = 10 % and 13 % of r̂^{I,J} = 20 µm), against the notes
// evaluated independently: a separate numpy script written from docs/model.md §1–4 (Hale factors,
// eq. 44, 34, 46 with denominator F_*,pY, 48, 49), not calling this library. Units µm, MPa, µN.
// These are the δ_p that docs/validation.md compares with the FE (Sec. 2).
TEST(Law, PaperCase2UnloadingMatchesAnIndependentEvaluationOfTheNotes) {
  const auto c = paper_case2();
  EXPECT_NEAR(c.equivalent_radius / 5.223735474555465, 1.0, 1e-12);
  EXPECT_NEAR(c.yield_overlap / 0.3545960495391769, 1.0, 1e-12);
  EXPECT_NEAR(c.yield_force / 48899.050614736065, 1.0, 1e-12);
  const struct {
    double max_overlap, plastic_radius, plastic_overlap, unloading_radius, loading_force, overlap, force;
  } expected[] = {
      {2.0, 8.790107702836337, 0.811451315239311, 21.81966862582169, 613279.628255928, 1.0, 38749.69922897366},
      {2.6, 9.879068170777373, 1.2252031062990956, 26.53679612093645, 841377.8154682171, 1.3, 10677.229720322326},
      {2.6, 9.879068170777373, 1.2252031062990956, 26.53679612093645, 841377.8154682171, 2.0, 355971.35348028166},
  };
  for (const auto& e : expected) {
    const UnloadingBranch branch = unloading_branch(c, e.max_overlap);
    EXPECT_NEAR(branch.plastic_radius / e.plastic_radius, 1.0, 1e-12);
    EXPECT_NEAR(branch.plastic_overlap / e.plastic_overlap, 1.0, 1e-12);
    EXPECT_NEAR(plastic_overlap(c, e.max_overlap) / e.plastic_overlap, 1.0, 1e-12);
    EXPECT_NEAR(branch.unloading_radius / e.unloading_radius, 1.0, 1e-12);
    EXPECT_NEAR(branch.loading_force / e.loading_force, 1.0, 1e-12);
    const LawResult result = evaluate_contact(c, e.overlap, e.max_overlap);
    EXPECT_EQ(result.regime, Regime::unloading);
    EXPECT_NEAR(result.force / e.force, 1.0, 1e-11) << e.max_overlap << " " << e.overlap;
  }
}

TEST(Law, NeverYieldedContactsUnloadAlongHertz) {
  const auto c = paper_case2();
  const double max_overlap = 0.9 * c.yield_overlap;
  const LawResult result = evaluate_contact(c, 0.5 * max_overlap, max_overlap);
  EXPECT_EQ(result.regime, Regime::elastic);
  EXPECT_DOUBLE_EQ(result.force, c.hertz_coefficient * std::pow(0.5 * max_overlap, 1.5));
}

TEST(Law, ReloadingRetracesUnloadingThenRejoinsTheEnvelope) {
  const auto c = paper_case1();
  const double peak = 6.0 * c.yield_overlap;
  std::vector<double> up;  // 0 … peak
  for (int i = 0; i <= 100; ++i) up.push_back(peak * i / 100.0);
  std::vector<double> path = up;                        // load
  path.insert(path.end(), up.rbegin() + 1, up.rend());  // unload to 0
  path.insert(path.end(), up.begin() + 1, up.end());    // reload to the same peak
  path.push_back(1.2 * peak);                           // and beyond: back on the envelope
  std::vector<LawResult> results(path.size());
  evaluate_along_path(c, path, results);
  for (int i = 0; i <= 100; ++i) {
    const auto& unload = results[100 + i];  // δ = peak (1 − i/100)
    const auto& reload = results[300 - i];  // the same δ on the way back up
    EXPECT_EQ(path[100 + i], path[300 - i]);
    EXPECT_EQ(unload.force, reload.force) << i;
  }
  EXPECT_EQ(results.back().regime, loading_force(c, 1.2 * peak).regime);
  EXPECT_DOUBLE_EQ(results.back().force, loading_force(c, 1.2 * peak).force);
}

TEST(Law, SwappingTheBodiesChangesNothing) {
  using ellc::testing::from_aspect;
  using ellc::testing::tip_constants;
  const auto i = from_aspect(1.25, 1.5, 4.675), j = from_aspect(0.5, 0.8, 4.675);
  for (HertzMode mode : {HertzMode::hale, HertzMode::exact}) {
    const auto ij = tip_constants(i, j, 0.3, -0.2, mode);
    const auto ji = tip_constants(j, i, -0.2, 0.3, mode);
    for (double factor : {0.5, 2.0, 10.0}) {
      const double overlap = factor * ij.yield_overlap;
      EXPECT_NEAR(evaluate_contact(ij, overlap, 0.0).force / evaluate_contact(ji, overlap, 0.0).force, 1.0, 1e-14);
      EXPECT_NEAR(evaluate_contact(ij, 0.7 * overlap, overlap).force,
                  evaluate_contact(ji, 0.7 * overlap, overlap).force,
                  1e-13 * evaluate_contact(ij, 0.7 * overlap, overlap).force + 1e-300);
    }
  }
}

TEST(Law, TwistingBothBodiesTogetherChangesNothing) {
  using ellc::testing::from_aspect;
  using ellc::testing::tip_constants;
  const auto a = tip_constants(from_aspect(1.25, 1.5, 4.675), from_aspect(0.5, 0.8, 4.675), 0.0, 0.0);
  const auto b = tip_constants(from_aspect(1.25, 1.5, 4.675), from_aspect(0.5, 0.8, 4.675), 0.9, 0.9);
  EXPECT_NEAR(a.equivalent_radius, b.equivalent_radius, 1e-14 * a.equivalent_radius);
  EXPECT_NEAR(a.f2, b.f2, 1e-14);
}

TEST(Law, RandomHistoriesNeverGiveNaNOrNegativeForce) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> aspect(0.3, 3.0), radius(0.5, 20.0), factor(-1.0, 60.0);
  for (int trial = 0; trial < 2000; ++trial) {
    const double mean = radius(rng);
    const auto c = ellc::testing::tip_constants(ellc::testing::from_aspect(aspect(rng), aspect(rng), mean),
                                                ellc::testing::from_aspect(aspect(rng), aspect(rng), radius(rng)), 0.0,
                                                0.0, trial % 2 ? HertzMode::exact : HertzMode::hale);
    ASSERT_TRUE(validation_error(c).empty()) << validation_error(c);
    double max_overlap = 0.0;
    for (int step = 0; step < 20; ++step) {
      const LawResult result = evaluate_contact(c, factor(rng) * c.yield_overlap, max_overlap);
      ASSERT_TRUE(std::isfinite(result.force));
      ASSERT_GE(result.force, 0.0);
      ASSERT_GE(result.max_overlap, max_overlap);
      max_overlap = result.max_overlap;
    }
  }
}

// The unloading curve kept by the caller (evaluate_contact_on_curve) or by a cache over a walk
// (evaluate_contact_cached, evaluate_along_path) must give exactly the bits of evaluate_contact:
// random walks load, unload, separate and reload past δ_* many times, so a cache that missed a
// change of δ_* would return the previous episode's curve.
TEST(Law, KeptAndCachedUnloadingCurvesGiveTheSameBits) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> aspect(0.3, 3.0), radius(0.5, 20.0), factor(-1.0, 14.0);
  int unloading_steps = 0, episodes = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const auto c = ellc::testing::tip_constants(ellc::testing::from_aspect(aspect(rng), aspect(rng), radius(rng)),
                                                ellc::testing::from_aspect(aspect(rng), aspect(rng), radius(rng)), 0.0,
                                                0.0, trial % 2 ? HertzMode::exact : HertzMode::hale);
    std::vector<double> path(40);
    for (double& overlap : path) overlap = factor(rng) * c.yield_overlap;
    std::vector<LawResult> along(path.size());
    evaluate_along_path(c, path, along);
    UnloadingCurveCache cache;
    double max_overlap = 0.0, last_curve_max = -1.0;
    for (std::size_t step = 0; step < path.size(); ++step) {
      const LawResult plain = evaluate_contact(c, path[step], max_overlap);
      const LawResult cached = evaluate_contact_cached(c, path[step], max_overlap, cache);
      const LawResult kept = evaluate_contact_on_curve(c, path[step], max_overlap, unloading_curve(c, max_overlap));
      for (const LawResult& other : {cached, kept, along[step]}) {
        ASSERT_EQ(other.force, plain.force) << trial << " " << step;
        ASSERT_EQ(other.max_overlap, plain.max_overlap);
        ASSERT_EQ(other.regime, plain.regime);
      }
      if (plain.regime == Regime::unloading) {
        ++unloading_steps;
        if (max_overlap != last_curve_max) ++episodes;
        last_curve_max = max_overlap;
      }
      max_overlap = plain.max_overlap;
    }
  }
  EXPECT_GT(unloading_steps, 2000);  // the walks do exercise the cache
  EXPECT_GT(episodes, 500);          // with many different δ_* per walk
}

// evaluate_contact_on_branch gives the law's bits and the elastic curve F = C x^{3/2} the force was
// on: Hertz (C, δ, 1) until the contact yields, the unloading curve of eq. (49) below δ_* (C_UL,
// δ − δ_p, R_e,pmax/R_e > 1) and at its top while a yielded contact loads, so the contact model
// need not derive that curve again.
TEST(Law, TheBranchIsTheElasticCurveTheForceWasOn) {
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> aspect(0.3, 3.0), radius(0.5, 20.0), factor(-1.0, 14.0);
  int unloading_steps = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const auto c = ellc::testing::tip_constants(ellc::testing::from_aspect(aspect(rng), aspect(rng), radius(rng)),
                                                ellc::testing::from_aspect(aspect(rng), aspect(rng), radius(rng)), 0.0,
                                                0.0, trial % 2 ? HertzMode::exact : HertzMode::hale);
    double max_overlap = 0.0;
    for (int step = 0; step < 40; ++step) {
      const double overlap = factor(rng) * c.yield_overlap;
      const LawResult plain = evaluate_contact(c, overlap, max_overlap);
      const LawOnBranch on_branch = evaluate_contact_on_branch(c, overlap, max_overlap);
      ASSERT_EQ(on_branch.law.force, plain.force) << trial << " " << step;
      ASSERT_EQ(on_branch.law.max_overlap, plain.max_overlap);
      ASSERT_EQ(on_branch.law.regime, plain.regime);
      const ElasticBranch& branch = on_branch.branch;
      // Below δ_* a yielded contact is on its unloading curve; loading beyond δ_Y, at the top of
      // the curve of its new δ_* (continuous stiffness where it turns); otherwise on Hertz's.
      const bool unloads = overlap > 0.0 && overlap < max_overlap && max_overlap > c.yield_overlap;
      const bool loads_yielded = overlap >= max_overlap && overlap > c.yield_overlap;
      if (unloads || loads_yielded) {
        const UnloadingBranch unloading = unloading_branch(c, unloads ? max_overlap : overlap);
        EXPECT_EQ(branch.coefficient, unloading.unloading_coefficient);
        EXPECT_EQ(branch.elastic_overlap, overlap - unloading.plastic_overlap);
        EXPECT_EQ(branch.radius_scale, unloading.unloading_radius / c.equivalent_radius);
        EXPECT_GT(branch.radius_scale, 1.0);  // the flattened patch: R_e,pmax > R_e
      } else {
        EXPECT_EQ(branch.coefficient, c.hertz_coefficient);
        EXPECT_EQ(branch.elastic_overlap, overlap);
        EXPECT_EQ(branch.radius_scale, 1.0);
      }
      if (plain.regime == Regime::unloading || (plain.regime == Regime::elastic && overlap < max_overlap)) {
        ++unloading_steps;
        EXPECT_EQ(plain.force, branch.coefficient * (branch.elastic_overlap * std::sqrt(branch.elastic_overlap)));
      }
      max_overlap = plain.max_overlap;
    }
  }
  EXPECT_GT(unloading_steps, 1000);
}

TEST(Law, SeparatedAtZeroOrNegativeOverlapKeepsHistoryForTheCaller) {
  const auto c = paper_case2();
  const LawResult result = evaluate_contact(c, -0.1, 1.0);
  EXPECT_EQ(result.force, 0.0);
  EXPECT_EQ(result.regime, Regime::separated);
  EXPECT_EQ(result.max_overlap, 1.0);
  EXPECT_EQ(evaluate_contact(c, std::numeric_limits<double>::quiet_NaN(), 0.0).force, 0.0);
}

TEST(Law, InvalidFitIsReportedByName) {
  LawParameters law;
  law.fit.lambda_offset = 0.0;  // λ_max < 1.6: pressure would fall after yield
  law.fit.lambda_amplitude = 0.1;
  const auto c = ellc::testing::tip_constants(ellc::testing::from_aspect(1, 1, 10),
                                              ellc::testing::from_aspect(1, 1, 10), 0.0, 0.0, HertzMode::hale, law);
  EXPECT_NE(validation_error(c).find("lambda_max"), std::string::npos);
}
}  // namespace
