#pragma once
// Files of the microstructure analysis: the voxel grid as VTK ImageData (.vti, one cell per voxel,
// cell data "solid", for ParaView) and as a NumPy array (.npy, uint8, shape (nz, ny, nx): index
// [iz, iy, ix]), the force network as VTK PolyData (.vtp: one line per contact between the two
// centres, cell data normal_force, max_overlap = δ_*, regime, particle_i, particle_j), and CSV
// tables of the profiles, the pore-size distribution and the force distribution. Each writer
// throws InputError naming the path when it cannot write.

#include <string>

#include "ellc/microstructure/distance_transform.hpp"
#include "ellc/microstructure/force_network.hpp"
#include "ellc/microstructure/packing.hpp"
#include "ellc/microstructure/profiles.hpp"
#include "ellc/microstructure/voxel_grid.hpp"

namespace ellc::microstructure {

void write_vti(const std::string& path, const VoxelGrid& grid);
void write_npy(const std::string& path, const VoxelGrid& grid);
void write_force_network_vtp(const std::string& path, const Packing& packing);
void write_profile_csv(const std::string& path, const HeightProfile& profile);
void write_pore_size_csv(const std::string& path, const PoreSizeDistribution& psd);
void write_force_distribution_csv(const std::string& path, const ForceDistribution& distribution);

}  // namespace ellc::microstructure
