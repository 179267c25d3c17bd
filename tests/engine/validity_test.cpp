// ValidityReport: contacts beyond c_c/r̂ = 0.16, where the paper's theory ends, are found and the
// force they carry is summed; the unbalanced-force ratio measures static equilibrium.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "ellc/engine/time_step.hpp"
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

// for_each_contact shows the same contacts as validity(), each with its c_c/r̂ and force: the
// spheres above (normal along the centre line, the floor's contact point under the centre), and
// a pressed bed of ellipsoids (normal force ≤ |F|, the wall's contact point δ/2 beyond it).
TEST(EngineContactView, EveryContactOnceWithItsForceOverlapAndSizeRatio) {
  const double radius = 4.0;
  ParticleSet spheres;
  const Eigen::Vector3d axes = Eigen::Vector3d::Constant(radius);
  const Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
  const double overlap = 0.25 * 0.25 * radius * radius / (radius / 2);  // c_c/r̂ = 0.25
  spheres.add(0, axes, 1.0, {60.0, 60.0, 50.0}, q);
  spheres.add(1, axes, 1.0, {60.0 + 2 * radius - overlap, 60.0, 50.0}, q);
  spheres.add(2, axes, 1.0, {100.0, 100.0, radius - 0.01}, q);
  const Simulation sim(testing::free_settings(NormalModel::hertz), spheres,
                       {Wall{0.0, 0.0, 1, {}}, Wall{150.0, 0.0, -1, {}}});
  std::vector<ContactView> seen;
  sim.for_each_contact([&](const ContactView& view) { seen.push_back(view); });
  ASSERT_EQ(seen.size(), 2U);
  const ContactView& pair = seen[0];
  EXPECT_EQ(pair.wall, -1);
  EXPECT_EQ(pair.i, 0U);
  EXPECT_EQ(pair.j, 1U);
  EXPECT_NEAR(pair.normal.x(), 1.0, 1e-12);
  EXPECT_NEAR(pair.overlap, overlap, 1e-12);
  EXPECT_EQ(pair.max_overlap, pair.overlap);
  EXPECT_NEAR(pair.size_ratio, 0.25, 1e-9);
  EXPECT_GT(pair.normal_force, 0.0);
  EXPECT_NEAR(pair.normal_force, pair.force.norm(), 1e-12 * pair.force.norm());
  EXPECT_EQ(pair.regime, Regime::elastic);
  const ContactView& floor = seen[1];
  EXPECT_EQ(floor.wall, kBottomWall);
  EXPECT_EQ(floor.i, 2U);
  EXPECT_EQ(floor.other, Eigen::Vector3d(100.0, 100.0, 0.0));
  EXPECT_EQ(floor.normal, Eigen::Vector3d(0.0, 0.0, -1.0));
  EXPECT_NEAR(floor.normal_force, -sim.walls()[kBottomWall].force.z(), 1e-12);

  // Ellipsoids pressed into the floor by the plate.
  ParticleSet bed = testing::colliding_packing(60, 7, 0.3, 0.0, 11);
  for (auto& v : bed.velocity) v.setZero();
  double top = 0.0;
  for (std::size_t k = 0; k < bed.size(); ++k) top = std::max(top, bed.position[k].z() + bed.bounding_radius[k]);
  EngineSettings settings = testing::free_settings(NormalModel::becker_kamlah);
  settings.box = testing::kCollidingBox;
  settings.dt = 0.2 * stable_time_step(bed, testing::kScaledDensity, settings.contact.material);
  Simulation pressed(settings, bed, {Wall{0.0, 0.0, 1, {}}, Wall{top, 0.0, -1, {}}});
  pressed.set_wall_velocity(kTopWall, -1.0);
  const double solid = pressed.particles().total_volume() / (settings.box.lx * settings.box.ly);
  while (pressed.gap() > solid / 0.55) pressed.step();
  const ValidityReport report = pressed.validity(0.05);
  const ContactCounts counts = pressed.contact_counts();
  std::size_t pairs = 0, walls = 0, beyond = 0;
  double pair_force = 0.0, plate_force = 0.0, largest = 0.0;
  pressed.for_each_contact([&](const ContactView& view) {
    (view.wall < 0 ? pairs : walls) += 1;
    beyond += view.size_ratio > 0.05 ? 1U : 0U;
    largest = std::max(largest, view.size_ratio);
    if (view.wall < 0) pair_force += view.force.norm();
    if (view.wall == kTopWall) {
      plate_force += view.force.z();
      // The midpoint of the deepest point, δ beyond the plate, and its projection on the plate.
      EXPECT_NEAR(view.other.z() - pressed.walls()[kTopWall].position, 0.5 * view.overlap, 1e-9);
    }
    EXPECT_GE(view.max_overlap, view.overlap - 1e-15);
    EXPECT_LE(view.normal_force, view.force.norm() * (1 + 1e-12));
    EXPECT_NEAR(view.normal.norm(), 1.0, 1e-12);
  });
  EXPECT_EQ(pairs, counts.particle_contacts);
  EXPECT_EQ(walls, counts.wall_contacts);
  EXPECT_GT(walls, 0U);
  EXPECT_EQ(beyond, report.pair_contacts_beyond + report.wall_contacts_beyond);
  EXPECT_EQ(largest, report.largest_ratio);
  EXPECT_NEAR(pair_force, report.pair_force, 1e-9 * report.pair_force);
  EXPECT_NEAR(plate_force, pressed.walls()[kTopWall].force.z(), 1e-9 * std::abs(plate_force));
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
