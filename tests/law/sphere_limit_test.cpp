// The sphere limit against Thornton (1997), "Coefficient of restitution for collinear collisions
// of elastic–perfectly plastic spheres", J. Appl. Mech. 64: closed forms written here in
// Thornton's own variables, independent of the library's formulation.
#include <gtest/gtest.h>

#include <cmath>

#include "law_fixtures.hpp"

namespace {
using namespace ellc;

struct Thornton {
  double modulus, radius, yield_pressure;  // E*, R* (effective radius), p_y
  double yield_overlap() const { return std::pow(M_PI * yield_pressure / (2.0 * modulus), 2) * radius; }
  double yield_force() const {
    return std::pow(M_PI * yield_pressure, 3) * radius * radius / (6.0 * modulus * modulus);
  }
  double loading(double overlap) const {
    if (overlap <= yield_overlap()) return 4.0 / 3.0 * modulus * std::sqrt(radius) * std::pow(overlap, 1.5);
    return yield_force() + M_PI * yield_pressure * radius * (overlap - yield_overlap());
  }
  // Unloading from F* at δ*: R_p = (4E*/3F*) ((2F* + F_y)/(2π p_y))^{3/2}, δ_p from F* on the new curve.
  double unloading(double overlap, double max_overlap) const {
    if (max_overlap <= yield_overlap()) return loading(overlap);  // never yielded: elastic both ways
    const double peak = loading(max_overlap);
    const double plastic_radius =
        4.0 * modulus / (3.0 * peak) * std::pow((2.0 * peak + yield_force()) / (2.0 * M_PI * yield_pressure), 1.5);
    const double plastic_overlap =
        max_overlap - std::pow(3.0 * peak / (4.0 * modulus * std::sqrt(plastic_radius)), 2.0 / 3.0);
    if (overlap <= plastic_overlap) return 0.0;
    return 4.0 / 3.0 * modulus * std::sqrt(plastic_radius) * std::pow(overlap - plastic_overlap, 1.5);
  }
};

TEST(SphereLimit, ElasticFullyPlasticVariantIsThornton1997) {
  for (double radius : {1.0, 4.675, 10.0}) {
    const Eigen::Vector3d sphere = Eigen::Vector3d::Constant(radius);
    for (HertzMode mode : {HertzMode::hale, HertzMode::exact}) {
      const auto c = ellc::testing::tip_constants(sphere, sphere, 0.0, 0.0, mode, LawParameters{}.elastic_fully_plastic());
      const Thornton thornton{c.effective_modulus, radius / 2.0, 1.6 * ellc::testing::kNmc.yield_stress};
      EXPECT_NEAR(c.equivalent_radius, radius / 2.0, 1e-14 * radius);
      EXPECT_NEAR(c.yield_overlap / thornton.yield_overlap(), 1.0, 1e-13);
      EXPECT_NEAR(c.yield_force / thornton.yield_force(), 1.0, 1e-13);
      for (double factor : {0.3, 1.0, 2.0, 10.0, 40.0}) {
        const double overlap = factor * c.yield_overlap;
        EXPECT_NEAR(evaluate_contact(c, overlap, 0.0).force / thornton.loading(overlap), 1.0, 1e-12);
        for (double fraction : {0.99, 0.9, 0.7, 0.5}) {
          const double back = fraction * overlap;
          const double expected = thornton.unloading(back, overlap);
          const double got = evaluate_contact(c, back, overlap).force;
          if (expected == 0.0)
            EXPECT_EQ(got, 0.0);
          else
            EXPECT_NEAR(got / expected, 1.0, 1e-10) << factor << " " << fraction;
        }
      }
    }
  }
}

TEST(SphereLimit, EqualSpheresSitAtAQuarterOfTheMeanRadiusSum) {
  // R_e / r̂^{I,J} = (R/2) / (2R) = 1/4, so λ_max = 1.05 e^{-1.155} + 2.42 and ε_max likewise.
  const Eigen::Vector3d sphere = Eigen::Vector3d::Constant(3.0);
  const auto c = ellc::testing::tip_constants(sphere, sphere);
  EXPECT_NEAR(c.lambda_max, 1.05 * std::exp(-4.62 / 4.0) + 2.42, 1e-14);
  EXPECT_NEAR(c.epsilon_max, 8.19 * std::exp(-6.14 / 4.0) + 1.14, 1e-14);
  // Fully plastic slope is π λ_max Y R_e (c_c² = R_e δ for spheres).
  const double overlap = 2.0 * c.plastic_limit_overlap;
  const double slope = (loading_force(c, overlap * 1.001).force - loading_force(c, overlap).force) / (overlap * 0.001);
  EXPECT_NEAR(slope / (M_PI * c.lambda_max * ellc::testing::kNmc.yield_stress * 1.5), 1.0, 1e-9);
}
}  // namespace
