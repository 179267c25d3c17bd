#pragma once
// The tortuosity factor of the pore phase from a steady diffusion solve on the voxel grid.
//
// Definition (docs/microstructure.md, "Tortuosity"): τ = ε D_bulk / D_eff, with ε the pore
// fraction of the grid, D_bulk the diffusivity in the pore (1 here) and D_eff the effective
// diffusivity of the whole grid along the axis: D_eff = J L / (A Δc), with J the steady flux
// through the grid when c = 1 on the inlet face and c = 0 on the outlet face (the two flux
// boundaries), and the other faces periodic where the box is, no-flux where it is not. Straight
// channels give τ = 1; Bruggeman's relation is τ = ε^(−1/2) (τ = ε^(1−α) with D_eff = ε^α).
//
// Discretisation: cell-centred finite volumes, one unknown per pore voxel connected to both
// faces; the conductance between neighbouring voxels is the harmonic mean of their diffusivities
// times face area over centre distance (exact for layers in series), and a face voxel is joined to
// its boundary by half a voxel. The symmetric positive definite system is solved matrix-free by
// conjugate gradients with a Jacobi preconditioner, starting from the linear profile. Sums are
// taken over fixed blocks in a fixed order, so the result does not depend on the thread count.

#include <optional>
#include <string>
#include <vector>

#include "ellc/microstructure/voxel_grid.hpp"

namespace ellc::microstructure {

struct DiffusionOptions {
  double relative_tolerance = 1e-7;  // CG stops at |r| ≤ tol |b| in the norm of D⁻¹ (Jacobi)
  int max_iterations = 20000;
};

struct DiffusionResult {
  int axis = 2;
  bool percolating = false;
  std::string reason;                  // why τ = ∞, when !percolating
  double porosity = 0.0;               // ε: pore fraction of the grid
  double conducting_fraction = 0.0;    // fraction of the grid in the solve (percolating pore)
  double effective_diffusivity = 0.0;  // D_eff / D_bulk
  double tortuosity = 0.0;             // τ = ε D_bulk / D_eff (infinity when !percolating)
  double flux_mismatch = 0.0;          // |J_in − J_out| / J_in: the solve's conservation check
  int iterations = 0;
  bool converged = false;
  double seconds = 0.0;
};

// General field: diffusivity[k] ≥ 0 per voxel (0: solid), bulk = the reference for τ (the pore
// diffusivity). The grid supplies shape, spacing and periodicity; its `solid` is not used.
// ε is the fraction of voxels with diffusivity > 0.
[[nodiscard]] DiffusionResult solve_diffusion(const VoxelGrid& grid, const std::vector<double>& diffusivity, int axis,
                                              double bulk = 1.0, const DiffusionOptions& options = {});
// The pore phase of the grid (solid == 0) with D = 1.
[[nodiscard]] DiffusionResult tortuosity_factor(const VoxelGrid& grid, int axis, const DiffusionOptions& options = {});

// τ at zero voxel size from τ at the voxel size h and at factor × h, by Richardson's
// extrapolation for first-order convergence (the voxel staircase's; docs/microstructure.md,
// "Resolution"): τ(0) ≈ τ(h) + (τ(h) − τ(factor h)) / (factor − 1). nullopt unless both are
// finite and positive and factor > 1. It is an estimate, worth as much as the first-order trend
// holds at these sizes (below).
[[nodiscard]] std::optional<double> extrapolated_tortuosity(double at_spacing, double at_coarse,
                                                            double factor) noexcept;

// The same where it can be trusted, as the analysis reports it. The first-order trend needs grids
// that resolve the particles: the coarse one at least kMinCoarseVoxelsPerSemiAxis voxels per
// smallest semi-axis (the default 5 per semi-axis with factor 2 gives exactly that; measured:
// at 2.5 the quick calendering example's estimate lands 1.3 % from the converged τ, at 1.0–1.2
// the line falls 15 % to 70 % short of it, to τ < 1 for the full example). And τ ≥ 1 always
// (D_eff ≤ ε D_bulk), so a line that ends below 1 is outside the first-order range.
inline constexpr double kMinCoarseVoxelsPerSemiAxis = 2.5;
struct TortuosityExtrapolation {
  std::optional<double> tortuosity;  // τ at zero voxel size
  std::string reason;                // why there is none, when there is none
};
[[nodiscard]] TortuosityExtrapolation extrapolate_tortuosity(double at_spacing, double at_coarse, double factor,
                                                             double coarse_voxels_per_semi_axis);

// The Bruggeman exponent α of D_eff/D_bulk = ε^α, i.e. τ = ε^(1 − α) (α = 1.5 is Bruggeman's
// τ = ε^(−1/2)): the least-squares fit of ln τ = (1 − α) ln ε through the origin over the states
// with a finite τ and 0 < ε < 1. NaN when there is no such state (callers print "n/a" and why).
[[nodiscard]] double fit_bruggeman_exponent(const std::vector<double>& porosity, const std::vector<double>& tortuosity);

}  // namespace ellc::microstructure
