#include "ellc/microstructure/profiles.hpp"

#include <algorithm>
#include <cmath>

#include "ellc/geometry/ellipsoid.hpp"

namespace ellc::microstructure {

double volume_below(double volume, double t) noexcept {
  const double s = std::clamp(t, -1.0, 1.0);
  return volume * (2.0 + 3.0 * s - s * s * s) / 4.0;
}

HeightProfile height_profile(const Packing& packing, int slabs, const VoxelGrid* grid) {
  HeightProfile profile;
  // With a grid, no more slabs than voxel layers, so that every slab has voxels.
  const int count = std::max(1, grid != nullptr && !grid->solid.empty() ? std::min(slabs, grid->shape[2]) : slabs);
  const auto n = static_cast<std::size_t>(count);
  const double z0 = packing.box.lower.z();
  const double height = packing.box.upper.z() - z0;
  const double dz = height / count;
  for (int k = 0; k < count; ++k) {
    profile.z_low.push_back(z0 + k * dz);
    profile.z_high.push_back(z0 + (k + 1) * dz);
  }
  const Eigen::Vector3d lengths = packing.box.lengths();
  const double slab_volume = lengths.x() * lengths.y() * dz;
  std::vector<double> solid(n, 0.0);
  for (std::size_t p = 0; p < packing.size(); ++p) {
    const Ellipsoid body(packing.semi_axes[p], Pose{packing.centres[p], packing.orientations[p]});
    const double half_height = std::sqrt(body.inverse_shape()(2, 2));
    const double volume = body.volume();
    // Images along a periodic z: the ones that reach into the box.
    const int images = packing.box.periodic[2] ? 1 + static_cast<int>(std::ceil(half_height / height)) : 0;
    for (int image = -images; image <= images; ++image) {
      const double zc = packing.centres[p].z() + image * height;
      if (zc + half_height <= z0 || zc - half_height >= z0 + height) continue;
      const auto first = static_cast<std::size_t>(
          std::clamp<long>(static_cast<long>(std::floor((zc - half_height - z0) / dz)), 0, count - 1));
      const auto last = static_cast<std::size_t>(
          std::clamp<long>(static_cast<long>(std::floor((zc + half_height - z0) / dz)), 0, count - 1));
      for (std::size_t k = first; k <= last; ++k)
        solid[k] += volume_below(volume, (profile.z_high[k] - zc) / half_height) -
                    volume_below(volume, (profile.z_low[k] - zc) / half_height);
    }
  }
  for (std::size_t k = 0; k < n; ++k) profile.porosity_analytic.push_back(1.0 - solid[k] / slab_volume);

  if (grid != nullptr && !grid->solid.empty()) {
    std::vector<double> solid_voxels(n, 0.0);
    std::vector<double> voxels(n, 0.0);
    const std::size_t layer = static_cast<std::size_t>(grid->shape[0]) * static_cast<std::size_t>(grid->shape[1]);
    for (int iz = 0; iz < grid->shape[2]; ++iz) {
      const double zc = grid->origin.z() + (iz + 0.5) * grid->spacing.z();
      const auto k =
          static_cast<std::size_t>(std::clamp<long>(static_cast<long>(std::floor((zc - z0) / dz)), 0, count - 1));
      std::size_t filled = 0;
      for (std::size_t v = static_cast<std::size_t>(iz) * layer; v < static_cast<std::size_t>(iz + 1) * layer; ++v)
        filled += grid->solid[v];
      solid_voxels[k] += static_cast<double>(filled);
      voxels[k] += static_cast<double>(layer);
    }
    for (std::size_t k = 0; k < n; ++k)
      profile.porosity_voxels.push_back(voxels[k] > 0 ? 1.0 - solid_voxels[k] / voxels[k] : std::nan(""));
  }

  profile.contacts.assign(n, 0);
  profile.mean_normal_force.assign(n, 0.0);
  for (const ContactRecord& contact : packing.contacts) {
    double z = contact.point.z() - z0;
    if (packing.box.periodic[2]) z -= height * std::floor(z / height);
    const auto k = static_cast<std::size_t>(std::clamp<long>(static_cast<long>(std::floor(z / dz)), 0, count - 1));
    ++profile.contacts[k];
    profile.mean_normal_force[k] += contact.normal_force;
  }
  for (std::size_t k = 0; k < n; ++k)
    if (profile.contacts[k] > 0) profile.mean_normal_force[k] /= static_cast<double>(profile.contacts[k]);
  return profile;
}

}  // namespace ellc::microstructure
