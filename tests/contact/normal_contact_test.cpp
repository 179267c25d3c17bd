// normal_contact(): from a contact geometry to the law's force, on walls and when separated.

#include "ellc/contact/normal_contact.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <utility>

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
  const NormalContact contact =
      normal_contact(geometry, ContactMaterial{1e5, 1e3}, 2.0, HertzMode::hale, LawParameters{}, 0.0);
  EXPECT_EQ(contact.law.force, 0.0);
  EXPECT_EQ(contact.law.regime, Regime::separated);
  EXPECT_EQ(contact.force_on_j, Eigen::Vector3d::Zero());
}

// The DEM's scope (ConstantsScope::law_reads) skips e² and, below first yield, the transition fit:
// the law must give the same bits, and every constant it leaves unset must be one the law did not
// read at this δ and δ_* (else the force would be NaN).
TEST(NormalContact, LawReadsScopeGivesTheSameBitsAsAllConstants) {
  const ContactMaterial material = mix(test::kNmc, test::kNmc);
  const auto same = [](double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; };
  int unset_transitions = 0, set_transitions = 0;
  for (const double ratio : {1.0, 1.3, 2.0, 7.0, 40.0, 3000.0}) {  // B/A: both branches of Hale's fit
    ContactGeometry geometry;
    geometry.relative = {0.25, 0.25 * ratio};
    const ContactConstants reference =
        make_contact_constants(material, hertz_shape(geometry.relative, HertzMode::hale), 8.0, LawParameters{});
    const double yield = reference.yield_overlap;
    // Overlaps × histories: elastic, transition, fully plastic on loading; unloading below each.
    for (const double overlap : {0.3 * yield, 0.999 * yield, 2.0 * yield, 0.5 * reference.plastic_limit_overlap,
                                 3.0 * reference.plastic_limit_overlap}) {
      for (const double history : {0.0, 0.5 * overlap, overlap, 1.01 * overlap, 0.9 * yield + overlap, 5.0 * yield}) {
        geometry.overlap = overlap;
        const NormalContact all = normal_contact(geometry, material, 8.0, HertzMode::hale, LawParameters{}, history);
        const NormalContact lean = normal_contact(geometry, material, 8.0, HertzMode::hale, LawParameters{}, history,
                                                  ConstantsScope::law_reads);
        SCOPED_TRACE(testing::Message() << "B/A " << ratio << ", delta/delta_Y " << overlap / yield
                                        << ", history/delta_Y " << history / yield);
        EXPECT_TRUE(same(lean.law.force, all.law.force));
        EXPECT_TRUE(same(lean.law.max_overlap, all.law.max_overlap));
        EXPECT_EQ(lean.law.regime, all.law.regime);
        EXPECT_TRUE(same(lean.branch.coefficient, all.branch.coefficient));
        EXPECT_TRUE(same(lean.branch.elastic_overlap, all.branch.elastic_overlap));
        EXPECT_TRUE(same(lean.branch.radius_scale, all.branch.radius_scale));
        const ContactConstants& l = lean.constants;
        const ContactConstants& a = all.constants;
        for (const auto& [mine, theirs] :
             {std::pair{l.effective_modulus, a.effective_modulus}, std::pair{l.yield_stress, a.yield_stress},
              std::pair{l.equivalent_radius, a.equivalent_radius}, std::pair{l.f1, a.f1}, std::pair{l.f2, a.f2},
              std::pair{l.contact_radius_sq_per_overlap, a.contact_radius_sq_per_overlap},
              std::pair{l.hertz_coefficient, a.hertz_coefficient}, std::pair{l.yield_pressure, a.yield_pressure},
              std::pair{l.yield_contact_radius, a.yield_contact_radius}, std::pair{l.yield_overlap, a.yield_overlap},
              std::pair{l.yield_force, a.yield_force}, std::pair{l.transition_exponent, a.transition_exponent},
              std::pair{l.yield_pressure_factor, a.yield_pressure_factor}})
          EXPECT_TRUE(same(mine, theirs));
        EXPECT_TRUE(std::isnan(l.eccentricity_sq));
        const bool beyond_yield = overlap > yield || history > yield;
        EXPECT_EQ(law_needs_transition(l, overlap, history), beyond_yield);
        if (beyond_yield) {
          ++set_transitions;
          EXPECT_TRUE(same(l.lambda_max, a.lambda_max));
          EXPECT_TRUE(same(l.epsilon_max, a.epsilon_max));
          EXPECT_TRUE(same(l.plastic_limit_overlap, a.plastic_limit_overlap));
        } else {
          ++unset_transitions;
          EXPECT_TRUE(std::isnan(l.lambda_max) && std::isnan(l.epsilon_max) && std::isnan(l.plastic_limit_overlap));
        }
      }
    }
  }
  EXPECT_GT(unset_transitions, 0);  // both cases were exercised
  EXPECT_GT(set_transitions, 0);
}

}  // namespace
}  // namespace ellc
