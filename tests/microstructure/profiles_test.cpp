// Profiles: the cap formula against a numerical integral of the sections, the slabs adding up to
// the particle volume, the analytic and voxel porosity agreeing, contacts binned by height.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "ellc/microstructure/profiles.hpp"
#include "microstructure/microstructure_support.hpp"

namespace ellc::microstructure {
namespace {

TEST(Profiles, CapVolumeIsTheIntegralOfTheSections) {
  // The section at t has area ∝ 1 − t²: the volume below t is V (2 + 3t − t³)/4.
  const double volume = 7.0;
  for (const double t : {-1.0, -0.6, 0.0, 0.3, 0.9, 1.0}) {
    double integral = 0.0;
    const int steps = 20000;
    for (int k = 0; k < steps; ++k) {
      const double s = -1.0 + (t + 1.0) * (k + 0.5) / steps;
      integral += (1.0 - s * s) * (t + 1.0) / steps;
    }
    EXPECT_NEAR(volume_below(volume, t), volume * integral * 3.0 / 4.0, 1e-8);
  }
  EXPECT_EQ(volume_below(volume, -3.0), 0.0);
  EXPECT_EQ(volume_below(volume, 3.0), volume);
}

TEST(Profiles, SlabsAddUpAndMatchTheVoxels) {
  Packing packing = test::random_ellipsoids(10, 16.0, 9);
  packing.box.periodic = {true, true, false};
  // A taller box, so that the slabs hold all of the particles (no semi-axis exceeds 2).
  packing.box.lower.z() = -4.0;
  packing.box.upper.z() = 20.0;
  Resolution resolution;
  resolution.spacing = 0.1;
  const VoxelGrid grid = voxelise(packing, resolution);
  const HeightProfile profile = height_profile(packing, 24, &grid);
  double solid = 0.0;
  const double slab_volume = 16.0 * 16.0 * 1.0;
  for (std::size_t k = 0; k < profile.z_low.size(); ++k) {
    solid += (1.0 - profile.porosity_analytic[k]) * slab_volume;
    EXPECT_NEAR(profile.porosity_voxels[k], profile.porosity_analytic[k], 0.01) << "slab " << k;
  }
  EXPECT_NEAR(solid, packing.particle_volume(), 1e-9 * packing.particle_volume());
}

TEST(Profiles, PeriodicZCountsTheImages) {
  // A sphere of radius 1 across z = 0 of a periodic box: its two halves in the first and last slab.
  Packing packing = test::one_sphere(1.0, {2.0, 2.0, 0.0}, 4.0);
  const HeightProfile profile = height_profile(packing, 4);
  const double half = 2.0 / 3.0 * std::numbers::pi;
  EXPECT_NEAR(1.0 - profile.porosity_analytic.front(), half / 16.0, 1e-12);
  EXPECT_NEAR(1.0 - profile.porosity_analytic.back(), half / 16.0, 1e-12);
  EXPECT_NEAR(profile.porosity_analytic[1], 1.0, 1e-15);
}

TEST(Profiles, ContactsAreBinnedByTheirPointWithTheirMeanForce) {
  Packing packing = test::one_sphere(1.0, {2.0, 2.0, 2.0}, 4.0);
  packing.centres.push_back({3.0, 3.0, 3.0});
  packing.semi_axes.emplace_back(1.0, 1.0, 1.0);
  packing.orientations.push_back(Eigen::Quaterniond::Identity());
  for (const auto& [z, force] : {std::pair{0.5, 2.0}, std::pair{0.7, 4.0}, std::pair{3.5, 1.0}}) {
    ContactRecord contact;
    contact.i = 0;
    contact.j = 1;
    contact.point = {1.0, 1.0, z};
    contact.normal_force = force;
    packing.contacts.push_back(contact);
  }
  const HeightProfile profile = height_profile(packing, 4);
  EXPECT_EQ(profile.contacts, (std::vector<long>{2, 0, 0, 1}));
  EXPECT_EQ(profile.mean_normal_force, (std::vector<double>{3.0, 0.0, 0.0, 1.0}));
}

}  // namespace
}  // namespace ellc::microstructure
