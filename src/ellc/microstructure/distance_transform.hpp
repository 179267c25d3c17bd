#pragma once
// The exact Euclidean distance transform of a voxel grid and the continuous pore-size
// distribution built on it.
//
// Distance transform: for every voxel, the squared distance (µm²) from its centre to the nearest
// centre of a "feature" voxel, exact (Felzenszwalb & Huttenlocher 2012, "Distance transforms of
// sampled functions", Theory of Computing 8: one exact 1-D lower-envelope pass per axis). Axes
// flagged periodic wrap; the spacing may differ per axis.
//
// Continuous pore-size distribution (Münch & Holzer 2008, J. Am. Ceram. Soc. 91: 4059, "cPSD"):
// V(r) = the fraction of the pore volume that can be covered by spheres of radius r lying wholly
// in the pore space, i.e. the morphological opening of the pore phase by a ball of radius r. Here
// a sphere "lies in the pore" when its centre voxel is at least r from every solid voxel centre.
// V falls from 1 (at r → 0) to 0; −dV/dr is the distribution, and r₅₀ (V = ½) its median radius.

#include <cstdint>
#include <vector>

#include "ellc/microstructure/voxel_grid.hpp"

namespace ellc::microstructure {

// Squared distance to the nearest voxel with feature[k] != 0 (infinity when there is none).
[[nodiscard]] std::vector<double> squared_distance_transform(const std::vector<std::uint8_t>& feature,
                                                             const VoxelGrid& grid);

struct PoreSizeDistribution {
  std::vector<double> radius;               // µm, ascending
  std::vector<double> cumulative_fraction;  // V(r): pore fraction coverable by spheres of radius r
  std::vector<double> density;              // −dV/dr between neighbouring radii (1/µm), at radius[k]
  double median_radius = 0.0;               // r₅₀: V(r₅₀) = ½ (linear interpolation)
  double largest_radius = 0.0;              // the largest sphere that fits (max of the distance map)
};

// The cPSD of the pore phase (solid == 0) of the grid at up to `max_radii` radii from one voxel
// (the smallest spacing) up to the largest inscribed radius, with V(0) = 1 first and V = 0 one
// smallest spacing beyond the largest radius last.
[[nodiscard]] PoreSizeDistribution continuous_pore_size_distribution(const VoxelGrid& grid, int max_radii = 32);

}  // namespace ellc::microstructure
