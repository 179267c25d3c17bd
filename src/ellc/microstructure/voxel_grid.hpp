#pragma once
// The solid phase of a packing on a voxel grid. Voxel (ix, iy, iz) is the box [lower + i h,
// lower + (i + 1) h) per axis; it is solid when its centre lies in some ellipsoid
// ((x − c)ᵀ M_w (x − c) ≤ 1, the exact inside test, solved per column of voxels along z for the
// interval of z inside). Axes periodic in the box wrap, so a particle across the boundary fills
// both sides. Each axis has n = max(1, round(L / h)) voxels and the spacing L / n, so a periodic
// axis tiles its period exactly (the spacings differ from the requested h by at most h / (2n)).

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "ellc/microstructure/packing.hpp"

namespace ellc::microstructure {

struct VoxelGrid {
  std::array<int, 3> shape{0, 0, 0};  // nx, ny, nz
  Eigen::Vector3d spacing = Eigen::Vector3d::Ones();
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  // the lower corner of voxel (0, 0, 0)
  std::array<bool, 3> periodic{false, false, false};
  std::vector<std::uint8_t> solid;  // 1 solid, 0 pore; x fastest: index = ix + nx (iy + ny iz)

  [[nodiscard]] std::size_t size() const noexcept {
    return static_cast<std::size_t>(shape[0]) * static_cast<std::size_t>(shape[1]) * static_cast<std::size_t>(shape[2]);
  }
  [[nodiscard]] std::size_t index(int ix, int iy, int iz) const noexcept {
    return static_cast<std::size_t>(ix) +
           static_cast<std::size_t>(shape[0]) *
               (static_cast<std::size_t>(iy) + static_cast<std::size_t>(shape[1]) * static_cast<std::size_t>(iz));
  }
  [[nodiscard]] double solid_fraction() const noexcept;
  [[nodiscard]] double porosity() const noexcept { return 1.0 - solid_fraction(); }
};

// The resolution: a spacing h (µm) or, when spacing is 0, h = smallest semi-axis / voxels_per_semi_axis.
// The grid is refused (InputError with the estimate) when voxels × bytes_per_voxel exceeds
// memory_limit_bytes. kAnalysisBytesPerVoxel is what the whole analysis needs at its peak (the
// tortuosity solve: six double fields, two byte masks, the grid).
inline constexpr double kAnalysisBytesPerVoxel = 59.0;
inline constexpr double kDefaultMemoryLimitBytes = 4.0 * 1024.0 * 1024.0 * 1024.0;  // 4 GiB
struct Resolution {
  double spacing = 0.0;
  double voxels_per_semi_axis = 5.0;
  double memory_limit_bytes = kDefaultMemoryLimitBytes;
  double bytes_per_voxel = kAnalysisBytesPerVoxel;
};

// The spacing the resolution asks for on this packing; InputError (naming `field`) when it is not > 0.
[[nodiscard]] double requested_spacing(const Packing& packing, const Resolution& resolution,
                                       const std::string& source = "resolution");
// The grid over the packing's box at that spacing, without voxels (shape, spacing, origin, periodic);
// InputError when it exceeds the memory limit, with the estimate.
[[nodiscard]] VoxelGrid empty_grid(const PackingBox& box, double spacing, const Resolution& resolution,
                                   const std::string& source = "resolution");
// Voxelises the packing (validated first) at the resolution.
[[nodiscard]] VoxelGrid voxelise(const Packing& packing, const Resolution& resolution,
                                 const std::string& source = "packing");
// Fills `grid.solid` (sized and cleared here) from the packing.
void fill_solid(const Packing& packing, VoxelGrid& grid);

// The packing voxelised again at `factor` × the spacing the fine grid was asked for (the
// resolution check of the tortuosity at a second, coarser resolution).
[[nodiscard]] VoxelGrid voxelise_coarser(const Packing& packing, double fine_spacing, double factor);

}  // namespace ellc::microstructure
