// The distance transform against brute force (periodic and not, anisotropic spacing), and the
// continuous pore-size distribution of slit pores, whose answer is known exactly.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "ellc/microstructure/distance_transform.hpp"

namespace ellc::microstructure {
namespace {

VoxelGrid grid_of(std::array<int, 3> shape, Eigen::Vector3d spacing, std::array<bool, 3> periodic) {
  VoxelGrid grid;
  grid.shape = shape;
  grid.spacing = spacing;
  grid.periodic = periodic;
  grid.solid.assign(grid.size(), 0);
  return grid;
}

TEST(DistanceTransform, EqualsBruteForce) {
  for (const bool periodic : {false, true}) {
    VoxelGrid grid = grid_of({9, 7, 6}, {0.5, 0.7, 1.1}, {periodic, periodic, false});
    std::mt19937 rng(4);
    for (auto& voxel : grid.solid) voxel = rng() % 17 == 0 ? 1 : 0;
    const std::vector<double> distance = squared_distance_transform(grid.solid, grid);
    for (int z = 0; z < 6; ++z)
      for (int y = 0; y < 7; ++y)
        for (int x = 0; x < 9; ++x) {
          double best = std::numeric_limits<double>::infinity();
          for (int z2 = 0; z2 < 6; ++z2)
            for (int y2 = 0; y2 < 7; ++y2)
              for (int x2 = 0; x2 < 9; ++x2) {
                if (grid.solid[grid.index(x2, y2, z2)] == 0) continue;
                double dx = std::abs(x - x2);
                double dy = std::abs(y - y2);
                if (periodic) {
                  dx = std::min(dx, 9.0 - dx);
                  dy = std::min(dy, 7.0 - dy);
                }
                best = std::min(best, std::pow(0.5 * dx, 2) + std::pow(0.7 * dy, 2) + std::pow(1.1 * (z - z2), 2));
              }
          ASSERT_NEAR(distance[grid.index(x, y, z)], best, 1e-12) << x << ' ' << y << ' ' << z;
        }
  }
}

TEST(PoreSizeDistribution, TwoSlitsGiveTwoSteps) {
  // Slits along x and y (periodic), bounded by solid layers in z: a narrow one of 4 pore layers
  // and a wide one of 12. Spheres up to the wide slit's largest radius fit in it and cover it;
  // the narrow one is covered only up to its own. V(r) is therefore 1, then 12/16, then 0.
  VoxelGrid grid = grid_of({8, 8, 19}, {1.0, 1.0, 1.0}, {true, true, false});
  for (int z : {0, 5, 18})
    for (int y = 0; y < 8; ++y)
      for (int x = 0; x < 8; ++x) grid.solid[grid.index(x, y, z)] = 1;
  const PoreSizeDistribution psd = continuous_pore_size_distribution(grid, 64);
  // Distances to the nearest solid centre: narrow slit z = 1..4 → at most 2; wide z = 6..17 → at most 6.
  EXPECT_DOUBLE_EQ(psd.largest_radius, 6.0);
  ASSERT_GT(psd.radius.size(), 3U);
  for (std::size_t k = 0; k < psd.radius.size(); ++k) {
    const double r = psd.radius[k];
    const double expected = r <= 2.0 ? 1.0 : (r <= 6.0 ? 12.0 / 16.0 : 0.0);
    EXPECT_DOUBLE_EQ(psd.cumulative_fraction[k], expected) << "r = " << r;
  }
  EXPECT_GT(psd.median_radius, 6.0);  // more than half of the pore is in the wide slit
}

}  // namespace
}  // namespace ellc::microstructure
