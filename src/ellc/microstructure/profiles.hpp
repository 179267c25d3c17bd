#pragma once
// Profiles along the height z (through the electrode thickness), in slabs of equal thickness
// between the box's lower and upper z.
//
// Porosity, analytically: an ellipsoid cut by the planes z = const has elliptical sections whose
// area falls as 1 − t² with t = (z − z_c)/h_z, h_z = sqrt(S_zz) its half height (S = R D² Rᵀ),
// so the volume below a plane is the closed form V (2 + 3t − t³)/4 for t in [−1, 1] (a cap of
// the ellipsoid), and the volume in a slab is the difference of two of them. The solid fraction
// of a slab is Σ (that volume)/(slab volume), over the particles and, on a periodic z axis, their
// images; overlaps of particles count twice (the DEM's overlaps are small; the voxel profile
// counts them once).
// Porosity from voxels: the pore fraction of the voxels whose centres lie in the slab.
// Contacts: the number of contacts whose contact point lies in the slab and their mean normal force.

#include <vector>

#include "ellc/microstructure/packing.hpp"
#include "ellc/microstructure/voxel_grid.hpp"

namespace ellc::microstructure {

// Volume of an ellipsoid of volume `volume` below the plane at t = (z − z_c)/h_z (closed form).
[[nodiscard]] double volume_below(double volume, double t) noexcept;

struct HeightProfile {
  std::vector<double> z_low;
  std::vector<double> z_high;
  std::vector<double> porosity_analytic;  // from the ellipsoid–slab intersection volumes
  std::vector<double> porosity_voxels;    // from the voxel grid (empty without one)
  std::vector<long> contacts;             // contacts with their point in the slab
  std::vector<double> mean_normal_force;  // µN, 0 in slabs without contacts
};

// `slabs` slabs between box.lower.z and box.upper.z. `grid` (may be null) adds the voxel porosity:
// each layer of voxels counts in the slab that holds its centre, and there are at most as many
// slabs as layers.
[[nodiscard]] HeightProfile height_profile(const Packing& packing, int slabs, const VoxelGrid* grid = nullptr);

}  // namespace ellc::microstructure
