// The sizes of issue 18 (docs/microstructure.md, "Speed and size"):
//   BM_Voxelise/10000: 10⁴ ellipsoids (r̂ = 4 µm, aspect ratios 1:[0.5, 2]:[0.5, 2], solid fraction
//     ~0.6, periodic box) at 5 voxels per smallest semi-axis, against the baseline
//     BM_VoxeliseEveryVoxelTested, the inside test at every voxel centre of each bounding box.
//   BM_Tortuosity200: the through-plane tortuosity solve of a 200³ grid of such a packing; the
//     counter peak_rss_gib is the process's peak resident memory (VmHWM) after it.
// Run: build/bench/bench_microstructure --benchmark_filter=Voxelise   (seconds)
//      build/bench/bench_microstructure --benchmark_filter=Tortuosity (minutes)

#include <benchmark/benchmark.h>

#include <cmath>
#include <fstream>
#include <random>
#include <string>

#include "ellc/geometry/ellipsoid.hpp"
#include "ellc/microstructure/tortuosity.hpp"
#include "ellc/microstructure/voxel_grid.hpp"

namespace {

using ellc::microstructure::Packing;

// `count` ellipsoids placed at random (overlaps allowed) at the given solid fraction (Σ V / box).
Packing random_packing(int count, double solid_fraction, unsigned seed) {
  Packing packing;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double mean_radius = 4.0;
  const double volume = count * 4.0 / 3.0 * M_PI * std::pow(mean_radius, 3);
  const double length = std::cbrt(volume / solid_fraction);
  packing.box.upper = Eigen::Vector3d::Constant(length);
  packing.box.periodic = {true, true, true};
  for (int k = 0; k < count; ++k) {
    const double b = std::exp(std::log(0.5) + unit(rng) * std::log(4.0));
    const double c = std::exp(std::log(0.5) + unit(rng) * std::log(4.0));
    const double a = mean_radius / std::cbrt(b * c);
    packing.semi_axes.emplace_back(a, a * b, a * c);
    packing.centres.emplace_back(length * unit(rng), length * unit(rng), length * unit(rng));
    packing.orientations.push_back(
        Eigen::Quaterniond(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5).normalized());
  }
  return packing;
}

double peak_rss_gib() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / (1024.0 * 1024.0);  // kB → GiB
  return 0.0;
}

void BM_Voxelise(benchmark::State& state) {
  const Packing packing = random_packing(static_cast<int>(state.range(0)), 0.6, 1);
  ellc::microstructure::Resolution resolution;
  resolution.voxels_per_semi_axis = 5.0;
  for (auto _ : state) {
    const auto grid = ellc::microstructure::voxelise(packing, resolution);
    benchmark::DoNotOptimize(grid.solid.data());
    state.counters["voxels"] = static_cast<double>(grid.size());
    state.counters["solid_fraction"] = grid.solid_fraction();
  }
}
BENCHMARK(BM_Voxelise)->Arg(10000)->Unit(benchmark::kSecond)->Iterations(1);

// Baseline: the inside test at every voxel centre of each particle's bounding box.
void BM_VoxeliseEveryVoxelTested(benchmark::State& state) {
  const Packing packing = random_packing(static_cast<int>(state.range(0)), 0.6, 1);
  ellc::microstructure::Resolution resolution;
  resolution.voxels_per_semi_axis = 5.0;
  for (auto _ : state) {
    auto grid = ellc::microstructure::empty_grid(
        packing.box, ellc::microstructure::requested_spacing(packing, resolution), resolution);
    grid.solid.assign(grid.size(), 0);
    const auto wrap = [](long i, long n) { return static_cast<std::size_t>(((i % n) + n) % n); };
    for (std::size_t p = 0; p < packing.size(); ++p) {
      const ellc::Ellipsoid body(packing.semi_axes[p], ellc::Pose{packing.centres[p], packing.orientations[p]});
      const auto box = body.axis_aligned_bounds();
      long lo[3];
      long hi[3];
      for (int a = 0; a < 3; ++a) {
        lo[a] = static_cast<long>(std::ceil((box.lower[a] - grid.origin[a]) / grid.spacing[a] - 0.5));
        hi[a] = static_cast<long>(std::floor((box.upper[a] - grid.origin[a]) / grid.spacing[a] - 0.5));
      }
      for (long iz = lo[2]; iz <= hi[2]; ++iz)
        for (long iy = lo[1]; iy <= hi[1]; ++iy)
          for (long ix = lo[0]; ix <= hi[0]; ++ix) {
            const Eigen::Vector3d x =
                grid.origin +
                (Eigen::Vector3d(static_cast<double>(ix), static_cast<double>(iy), static_cast<double>(iz)).array() +
                 0.5)
                    .matrix()
                    .cwiseProduct(grid.spacing);
            if (body.implicit_value(x) <= 0.0)
              grid.solid[wrap(ix, grid.shape[0]) +
                         static_cast<std::size_t>(grid.shape[0]) *
                             (wrap(iy, grid.shape[1]) +
                              static_cast<std::size_t>(grid.shape[1]) * wrap(iz, grid.shape[2]))] = 1;
          }
    }
    benchmark::DoNotOptimize(grid.solid.data());
    state.counters["solid_fraction"] = grid.solid_fraction();
  }
}
BENCHMARK(BM_VoxeliseEveryVoxelTested)->Arg(10000)->Unit(benchmark::kSecond)->Iterations(1);

void BM_Tortuosity200(benchmark::State& state) {
  // A packing at solid fraction 0.6 (overlaps allowed: porosity ~0.4 after them), voxelised to 200³.
  const Packing packing = random_packing(1500, 0.8, 2);
  ellc::microstructure::Resolution resolution;
  resolution.spacing = packing.box.upper.x() / 200.0;
  const auto grid = ellc::microstructure::voxelise(packing, resolution);
  for (auto _ : state) {
    const auto result = ellc::microstructure::tortuosity_factor(grid, 2);
    state.counters["porosity"] = result.porosity;
    state.counters["tortuosity"] = result.tortuosity;
    state.counters["iterations"] = result.iterations;
  }
  state.counters["voxels"] = static_cast<double>(grid.size());
  state.counters["peak_rss_gib"] = peak_rss_gib();
}
BENCHMARK(BM_Tortuosity200)->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace
