#include "ellc/microstructure/voxel_grid.hpp"

#include <algorithm>
#include <cmath>

#include "ellc/geometry/ellipsoid.hpp"
#include "ellc/io/input_error.hpp"

namespace ellc::microstructure {

double VoxelGrid::solid_fraction() const noexcept {
  if (solid.empty()) return 0.0;
  std::size_t count = 0;
  for (const std::uint8_t value : solid) count += value;
  return static_cast<double>(count) / static_cast<double>(solid.size());
}

double requested_spacing(const Packing& packing, const Resolution& resolution, const std::string& source) {
  if (resolution.spacing != 0.0) {
    if (!(std::isfinite(resolution.spacing) && resolution.spacing > 0.0))
      throw InputError(source, "spacing", format_number(resolution.spacing), "a voxel size > 0 (µm)");
    return resolution.spacing;
  }
  if (!(std::isfinite(resolution.voxels_per_semi_axis) && resolution.voxels_per_semi_axis > 0.0))
    throw InputError(source, "voxels_per_semi_axis", format_number(resolution.voxels_per_semi_axis),
                     "a number of voxels per smallest semi-axis > 0");
  if (packing.size() == 0)
    throw InputError(source, "voxels_per_semi_axis", format_number(resolution.voxels_per_semi_axis),
                     "a spacing instead: the packing has no particles to take the smallest semi-axis from");
  return packing.smallest_semi_axis() / resolution.voxels_per_semi_axis;
}

VoxelGrid empty_grid(const PackingBox& box, double spacing, const Resolution& resolution, const std::string& source) {
  if (!(std::isfinite(spacing) && spacing > 0.0))
    throw InputError(source, "spacing", format_number(spacing), "a voxel size > 0 (µm)");
  VoxelGrid grid;
  grid.origin = box.lower;
  grid.periodic = box.periodic;
  double voxels = 1.0;
  for (int axis = 0; axis < 3; ++axis) {
    const double length = box.upper[axis] - box.lower[axis];
    const double count = std::max(1.0, std::round(length / spacing));
    voxels *= count;
    grid.shape[static_cast<std::size_t>(axis)] = count < 2.0e9 ? static_cast<int>(count) : 0;
    grid.spacing[axis] = length / count;
  }
  const double bytes = voxels * resolution.bytes_per_voxel;
  if (!(bytes <= resolution.memory_limit_bytes) || grid.size() == 0) {
    const double gib = 1024.0 * 1024.0 * 1024.0;
    char text[200];
    std::snprintf(text, sizeof text, "%.4g um: %.4g x %.4g x %.4g = %.3g voxels, about %.3g GiB", spacing,
                  std::max(1.0, std::round((box.upper.x() - box.lower.x()) / spacing)),
                  std::max(1.0, std::round((box.upper.y() - box.lower.y()) / spacing)),
                  std::max(1.0, std::round((box.upper.z() - box.lower.z()) / spacing)), voxels, bytes / gib);
    throw InputError(source, "spacing", text,
                     "a grid within the memory limit of " + format_number(resolution.memory_limit_bytes / gib) +
                         " GiB (" + format_number(resolution.bytes_per_voxel) +
                         " bytes per voxel): a coarser resolution");
  }
  return grid;
}

namespace {

// Voxel indices whose centres lie in [low, high] along an axis: first, last (last < first: none).
std::pair<long, long> centre_range(double low, double high, double origin, double spacing) {
  return {static_cast<long>(std::ceil((low - origin) / spacing - 0.5)),
          static_cast<long>(std::floor((high - origin) / spacing - 0.5))};
}

long wrap(long index, long count) {
  const long r = index % count;
  return r < 0 ? r + count : r;
}

}  // namespace

void fill_solid(const Packing& packing, VoxelGrid& grid) {
  grid.solid.assign(grid.size(), 0);
  const long nx = grid.shape[0];
  const long ny = grid.shape[1];
  const long nz = grid.shape[2];
  const Eigen::Vector3d& h = grid.spacing;
  const Eigen::Vector3d& o = grid.origin;
  for (std::size_t p = 0; p < packing.size(); ++p) {
    const Ellipsoid body(packing.semi_axes[p], Pose{packing.centres[p], packing.orientations[p]});
    const Eigen::Matrix3d& m = body.shape();  // (x − c)ᵀ M_w (x − c) ≤ 1 inside
    const Eigen::Vector3d& c = body.center();
    const Eigen::Vector3d reach = body.inverse_shape().diagonal().cwiseSqrt();  // half extents of the AABB
    const auto [x0, x1] = centre_range(c.x() - reach.x(), c.x() + reach.x(), o.x(), h.x());
    const auto [y0, y1] = centre_range(c.y() - reach.y(), c.y() + reach.y(), o.y(), h.y());
    for (long ix = x0; ix <= x1; ++ix) {
      if (!grid.periodic[0] && (ix < 0 || ix >= nx)) continue;
      const double dx = o.x() + (static_cast<double>(ix) + 0.5) * h.x() - c.x();
      const std::size_t gx = static_cast<std::size_t>(wrap(ix, nx));
      for (long iy = y0; iy <= y1; ++iy) {
        if (!grid.periodic[1] && (iy < 0 || iy >= ny)) continue;
        const double dy = o.y() + (static_cast<double>(iy) + 0.5) * h.y() - c.y();
        // M_zz dz² + 2 b dz + q ≤ 1 along the column: the interval of dz inside.
        const double b = m(0, 2) * dx + m(1, 2) * dy;
        const double q = m(0, 0) * dx * dx + 2.0 * m(0, 1) * dx * dy + m(1, 1) * dy * dy;
        const double discriminant = b * b - m(2, 2) * (q - 1.0);
        if (discriminant < 0.0) continue;
        const double root = std::sqrt(discriminant);
        const auto [z0, z1] = centre_range(c.z() + (-b - root) / m(2, 2), c.z() + (-b + root) / m(2, 2), o.z(), h.z());
        const std::size_t gy = static_cast<std::size_t>(wrap(iy, ny));
        for (long iz = z0; iz <= z1; ++iz) {
          if (!grid.periodic[2] && (iz < 0 || iz >= nz)) continue;
          const std::size_t gz = static_cast<std::size_t>(wrap(iz, nz));
          grid.solid[gx + static_cast<std::size_t>(nx) * (gy + static_cast<std::size_t>(ny) * gz)] = 1;
        }
      }
    }
  }
}

VoxelGrid voxelise(const Packing& packing, const Resolution& resolution, const std::string& source) {
  validate_packing(packing, source);
  VoxelGrid grid = empty_grid(packing.box, requested_spacing(packing, resolution), resolution);
  fill_solid(packing, grid);
  return grid;
}

VoxelGrid voxelise_coarser(const Packing& packing, double fine_spacing, double factor) {
  Resolution resolution;
  resolution.memory_limit_bytes = 1e300;  // coarser than a grid that passed the limit
  VoxelGrid grid = empty_grid(packing.box, fine_spacing * factor, resolution);
  fill_solid(packing, grid);
  return grid;
}

}  // namespace ellc::microstructure
