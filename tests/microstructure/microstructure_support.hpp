#pragma once
// Small packings with known volume fractions for the microstructure tests.

#include <random>

#include "ellc/microstructure/packing.hpp"
#include "ellc/microstructure/voxel_grid.hpp"

namespace ellc::test {

// One sphere of `radius` at `centre` in the box [0, length]³, periodic along every axis.
inline microstructure::Packing one_sphere(double radius, const Eigen::Vector3d& centre, double length,
                                          bool periodic = true) {
  microstructure::Packing packing;
  packing.centres.push_back(centre);
  packing.semi_axes.emplace_back(radius, radius, radius);
  packing.orientations.push_back(Eigen::Quaterniond::Identity());
  packing.box.upper = Eigen::Vector3d::Constant(length);
  packing.box.periodic = {periodic, periodic, periodic};
  return packing;
}

// `count` ellipsoids of random shape and orientation whose bounding spheres do not overlap, in a
// periodic box: the solid fraction is exactly Σ V / box volume.
inline microstructure::Packing random_ellipsoids(int count, double length, unsigned seed) {
  microstructure::Packing packing;
  packing.box.upper = Eigen::Vector3d::Constant(length);
  packing.box.periodic = {true, true, true};
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> reach;
  for (int attempt = 0; attempt < 100000 && static_cast<int>(packing.size()) < count; ++attempt) {
    const Eigen::Vector3d axes(1.0 + unit(rng), 1.0 + unit(rng), 1.0 + unit(rng));
    const Eigen::Vector3d centre(length * unit(rng), length * unit(rng), length * unit(rng));
    bool free = true;
    for (std::size_t k = 0; k < packing.size() && free; ++k) {
      Eigen::Vector3d d = centre - packing.centres[k];
      for (int a = 0; a < 3; ++a) d[a] -= length * std::round(d[a] / length);
      free = d.norm() > axes.maxCoeff() + reach[k];
    }
    if (!free) continue;
    packing.centres.push_back(centre);
    packing.semi_axes.push_back(axes);
    packing.orientations.push_back(
        Eigen::Quaterniond(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5).normalized());
    reach.push_back(axes.maxCoeff());
  }
  return packing;
}

}  // namespace ellc::test
