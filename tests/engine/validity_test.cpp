// ValidityReport: contacts beyond c_c/r̂ = 0.16, where the paper's theory ends, are found and the
// force they carry is summed; the unbalanced-force ratio measures static equilibrium.

#include <gtest/gtest.h>

#include <cmath>

#include "engine_support.hpp"

namespace ellc::engine {
namespace {

// Two pairs of equal spheres (radius R, R_e = R/2) at rest: c_c/r̂ = sqrt(R_e δ)/R is 0.1 for one
// pair and 0.25 for the other. A fifth sphere sits on the floor at c_c/r̂ = 0.2 (R_e = R).
TEST(EngineValidity, ContactsBeyondTheFiniteDeformationLimitAreCountedWithTheirForce) {
  const double radius = 4.0;
  const auto overlap_for = [&](double ratio, double equivalent_radius) {
    return ratio * ratio * radius * radius / equivalent_radius;
  };
  ParticleSet particles;
  const Eigen::Vector3d axes = Eigen::Vector3d::Constant(radius);
  const Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
  const double small = overlap_for(0.10, radius / 2);
  const double large = overlap_for(0.25, radius / 2);
  particles.add(0, axes, 1.0, {20.0, 20.0, 50.0}, q);
  particles.add(1, axes, 1.0, {20.0 + 2 * radius - small, 20.0, 50.0}, q);
  particles.add(2, axes, 1.0, {60.0, 60.0, 50.0}, q);
  particles.add(3, axes, 1.0, {60.0 + 2 * radius - large, 60.0, 50.0}, q);
  particles.add(4, axes, 1.0, {100.0, 100.0, radius - overlap_for(0.20, radius)}, q);
  EngineSettings settings = testing::free_settings(NormalModel::hertz);  // no yield: plain Hertz forces
  const Simulation sim(settings, particles, {Wall{0.0, 0.0, 1, {}}, Wall{150.0, 0.0, -1, {}}});

  const ValidityReport report = sim.validity();
  EXPECT_EQ(report.pair_contacts, 2U);
  EXPECT_EQ(report.pair_contacts_beyond, 1U);
  EXPECT_EQ(report.wall_contacts, 1U);
  EXPECT_EQ(report.wall_contacts_beyond, 1U);
  EXPECT_NEAR(report.largest_ratio, 0.25, 1e-9);
  // Hertz: F ∝ δ^{3/2}, so the deep pair carries (0.25/0.1)^3 of the shallow one's force.
  EXPECT_NEAR(report.pair_force_beyond / (report.pair_force - report.pair_force_beyond), std::pow(2.5, 3.0), 1e-6);
  EXPECT_EQ(report.wall_force_beyond, report.wall_force);
  EXPECT_EQ(sim.validity(0.3).pair_contacts_beyond, 0U);
}

// A sphere squeezed equally by floor and plate is in equilibrium (ratio 0); one pushed by the
// floor alone is not (ratio 1: its net force is its only contact force).
TEST(EngineEquilibrium, UnbalancedForceRatioIsNetOverContactForce) {
  const double radius = 4.0;
  const double overlap = 0.02;
  ParticleSet particles;
  particles.add(0, Eigen::Vector3d::Constant(radius), 1.0, {20.0, 20.0, radius - overlap},
                Eigen::Quaterniond::Identity());
  const EngineSettings settings = testing::free_settings(NormalModel::hertz);
  const Simulation squeezed(settings, particles, {Wall{0.0, 0.0, 1, {}}, Wall{2 * (radius - overlap), 0.0, -1, {}}});
  EXPECT_LT(squeezed.unbalanced_force_ratio(), 1e-12);
  const Simulation pushed(settings, particles, {Wall{0.0, 0.0, 1, {}}, Wall{100.0, 0.0, -1, {}}});
  EXPECT_NEAR(pushed.unbalanced_force_ratio(), 1.0, 1e-12);
}

}  // namespace
}  // namespace ellc::engine
