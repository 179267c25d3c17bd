#pragma once
// The whole microstructure analysis of one packing, as `ellc analyse` and `ellc dem`'s
// [analysis] run it (docs/microstructure.md): voxelise, profiles, pore sizes, tortuosity along
// x, y, z and pore sizes at the resolution and at a coarser one (the resolution check), force
// distribution.

#include <array>
#include <iosfwd>
#include <optional>
#include <string>

#include "ellc/microstructure/distance_transform.hpp"
#include "ellc/microstructure/force_network.hpp"
#include "ellc/microstructure/packing.hpp"
#include "ellc/microstructure/profiles.hpp"
#include "ellc/microstructure/tortuosity.hpp"
#include "ellc/microstructure/voxel_grid.hpp"

namespace ellc::microstructure {

struct AnalysisOptions {
  Resolution resolution;
  std::array<bool, 3> tortuosity_axes{true, true, true};  // x, y, z
  double coarse_factor = 2.0;   // the resolution check: τ and r₅₀ again at this × the spacing (≤ 1: none)
  double slab_thickness = 0.0;  // µm; 0 → half the mean particle radius (abc)^(1/3)
  int pore_size_radii = 24;
  DiffusionOptions diffusion;
};

struct AnalysisReport {
  std::size_t particles = 0;
  std::size_t contacts = 0;
  double spacing = 0.0;            // the requested voxel size, µm
  VoxelGrid grid;                  // the voxelised solid
  double porosity_analytic = 0.0;  // 1 − Σ particle volumes / box volume (overlaps counted twice)
  double porosity_voxels = 0.0;
  double voxelise_seconds = 0.0;
  HeightProfile profile;
  PoreSizeDistribution pore_sizes;
  ForceDistribution forces;
  std::array<std::optional<DiffusionResult>, 3> tortuosity;         // at the spacing
  std::array<std::optional<DiffusionResult>, 3> tortuosity_coarse;  // at coarse_factor × the spacing
  std::optional<PoreSizeDistribution> pore_sizes_coarse;            // at coarse_factor × the spacing
  std::array<TortuosityExtrapolation, 3> tortuosity_extrapolated;   // to zero voxel size, or why not
  double coarse_spacing = 0.0;
  std::array<int, 3> coarse_shape{0, 0, 0};
};

// Validates the packing (InputError naming the row) and the resolution (InputError with the
// memory estimate), then runs every analysis.
[[nodiscard]] AnalysisReport analyse(const Packing& packing, const AnalysisOptions& options,
                                     const std::string& source = "packing");

// Writes into `directory` (created): solid.vti, solid.npy, profile.csv, pore_size_distribution.csv,
// tortuosity.csv, force_network.vtp, normal_force_pdf.csv, packing.csv (+ packing_contacts.csv)
// and analysis.txt (write_analysis_summary). The PNGs are drawn from the CSVs by
// `python3 -m ellc.plots analysis DIRECTORY`.
void write_analysis(const std::string& directory, const Packing& packing, const AnalysisReport& report);
// A TOML document, one key per line: grid, porosities, τ per axis and the pore radii at both
// resolutions (inf and the reason when a direction does not percolate), forces.
void write_analysis_summary(std::ostream& out, const AnalysisReport& report);

}  // namespace ellc::microstructure
