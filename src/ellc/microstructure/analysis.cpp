#include "ellc/microstructure/analysis.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <string>
#include <type_traits>

#include "ellc/io/input_error.hpp"
#include "ellc/io/toml_text.hpp"
#include "ellc/microstructure/export.hpp"

namespace ellc::microstructure {

namespace {

constexpr std::array<char, 3> kAxes{'x', 'y', 'z'};

double mean_radius(const Packing& packing) {
  double sum = 0.0;
  for (const auto& axes : packing.semi_axes) sum += std::cbrt(axes.prod());
  return packing.size() > 0 ? sum / static_cast<double>(packing.size()) : 0.0;
}

std::string number_or_inf(double value) { return std::isfinite(value) ? format_number(value) : "inf"; }

template <typename Value>
std::string toml_array(const std::array<Value, 3>& values) {
  std::string text = "[";
  for (std::size_t k = 0; k < 3; ++k) {
    if (k > 0) text += ", ";
    if constexpr (std::is_floating_point_v<Value>)
      text += toml_float(values[k]);
    else
      text += std::to_string(values[k]);
  }
  return text + "]";
}

}  // namespace

AnalysisReport analyse(const Packing& packing, const AnalysisOptions& options, const std::string& source) {
  validate_packing(packing, source);
  AnalysisReport report;
  report.particles = packing.size();
  report.contacts = packing.contacts.size();
  report.spacing = requested_spacing(packing, options.resolution, source);
  report.grid = empty_grid(packing.box, report.spacing, options.resolution, source);
  const auto start = std::chrono::steady_clock::now();
  fill_solid(packing, report.grid);
  report.voxelise_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  report.porosity_analytic = 1.0 - packing.particle_volume() / packing.box.volume();
  report.porosity_voxels = report.grid.porosity();

  const double slab = options.slab_thickness > 0.0 ? options.slab_thickness : 0.5 * mean_radius(packing);
  const double height = packing.box.upper.z() - packing.box.lower.z();
  const int slabs = slab > 0.0 ? std::max(1, static_cast<int>(std::lround(height / slab))) : 1;
  report.profile = height_profile(packing, slabs, &report.grid);
  report.pore_sizes = continuous_pore_size_distribution(report.grid, options.pore_size_radii);
  report.forces = normal_force_distribution(packing.contacts);

  for (std::size_t axis = 0; axis < 3; ++axis)
    if (options.tortuosity_axes[axis])
      report.tortuosity[axis] = tortuosity_factor(report.grid, static_cast<int>(axis), options.diffusion);
  if (options.coarse_factor > 1.0) {
    const VoxelGrid coarse = voxelise_coarser(packing, report.spacing, options.coarse_factor);
    report.coarse_spacing = report.spacing * options.coarse_factor;
    report.coarse_shape = coarse.shape;
    report.pore_sizes_coarse = continuous_pore_size_distribution(coarse, options.pore_size_radii);
    const double coarse_voxels_per_semi_axis = packing.smallest_semi_axis() / report.coarse_spacing;
    for (std::size_t axis = 0; axis < 3; ++axis)
      if (const auto& fine = report.tortuosity[axis]) {  // the axes asked for
        const DiffusionResult at_coarse = tortuosity_factor(coarse, static_cast<int>(axis), options.diffusion);
        report.tortuosity_extrapolated[axis] = extrapolate_tortuosity(
            fine->tortuosity, at_coarse.tortuosity, options.coarse_factor, coarse_voxels_per_semi_axis);
        report.tortuosity_coarse[axis] = at_coarse;
      }
  }
  return report;
}

void write_analysis_summary(std::ostream& out, const AnalysisReport& report) {
  const VoxelGrid& grid = report.grid;
  out << "particles = " << report.particles << "\ncontacts = " << report.contacts
      << "\nvoxel_size_um = " << toml_float(report.spacing) << "\ngrid = " << toml_array(grid.shape)
      << "\ngrid_spacing_um = "
      << toml_array(std::array<double, 3>{grid.spacing.x(), grid.spacing.y(), grid.spacing.z()})
      << "\nvoxelise_seconds = " << toml_float(report.voxelise_seconds)
      << "\nporosity_analytic = " << toml_float(report.porosity_analytic)
      << "\nporosity_voxels = " << toml_float(report.porosity_voxels)
      << "\npore_radius_median_um = " << toml_float(report.pore_sizes.median_radius)
      << "\npore_radius_largest_um = " << toml_float(report.pore_sizes.largest_radius)
      << "\nmean_normal_force_uN = " << toml_float(report.forces.mean_force) << '\n';
  const auto write = [&](const std::optional<DiffusionResult>& result, const std::string& suffix) {
    if (!result) return;
    const char axis = kAxes[static_cast<std::size_t>(result->axis)];
    out << "tortuosity_" << axis << suffix << " = " << toml_float(result->tortuosity) << '\n';
    if (!result->reason.empty())
      out << "tortuosity_" << axis << suffix << "_note = " << toml_string(result->reason) << '\n';
  };
  for (const auto& result : report.tortuosity) write(result, "");
  if (report.coarse_spacing > 0.0) {
    out << "coarse_voxel_size_um = " << toml_float(report.coarse_spacing)
        << "\ncoarse_grid = " << toml_array(report.coarse_shape) << '\n';
    if (const auto& psd = report.pore_sizes_coarse)
      out << "pore_radius_median_um_coarse = " << toml_float(psd->median_radius)
          << "\npore_radius_largest_um_coarse = " << toml_float(psd->largest_radius) << '\n';
    for (const auto& result : report.tortuosity_coarse) write(result, "_coarse");
    for (std::size_t axis = 0; axis < 3; ++axis) {
      const TortuosityExtrapolation& line = report.tortuosity_extrapolated[axis];
      if (line.tortuosity)
        out << "tortuosity_" << kAxes[axis] << "_extrapolated = " << toml_float(*line.tortuosity) << '\n';
      else if (!line.reason.empty())  // empty where no line was attempted (an axis not asked for)
        out << "tortuosity_" << kAxes[axis] << "_extrapolated_note = " << toml_string(line.reason) << '\n';
    }
  }
}

void write_analysis(const std::string& directory, const Packing& packing, const AnalysisReport& report) {
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error) throw InputError(directory, "output directory", directory, "a folder that can be created");
  const auto in = [&](const char* name) { return (std::filesystem::path(directory) / name).string(); };
  write_vti(in("solid.vti"), report.grid);
  write_npy(in("solid.npy"), report.grid);
  write_profile_csv(in("profile.csv"), report.profile);
  write_pore_size_csv(in("pore_size_distribution.csv"), report.pore_sizes);
  write_force_distribution_csv(in("normal_force_pdf.csv"), report.forces);
  write_force_network_vtp(in("force_network.vtp"), packing);
  write_packing_file(in("packing.csv"), packing);
  {
    std::ofstream out(in("tortuosity.csv"));
    out.precision(10);
    out << "# tau = porosity * D_bulk / D_eff (docs/microstructure.md); inf: no percolating pore path\n"
        << "axis,voxel_size_um,nx,ny,nz,porosity,conducting_fraction,effective_diffusivity,tortuosity,iterations,"
           "converged,flux_mismatch,seconds,note\n";
    const auto row = [&](const std::optional<DiffusionResult>& r, double size, const std::array<int, 3>& shape) {
      if (!r) return;
      out << kAxes[static_cast<std::size_t>(r->axis)] << ',' << size << ',' << shape[0] << ',' << shape[1] << ','
          << shape[2] << ',' << r->porosity << ',' << r->conducting_fraction << ',' << r->effective_diffusivity << ','
          << number_or_inf(r->tortuosity) << ',' << r->iterations << ',' << (r->converged ? 1 : 0) << ','
          << r->flux_mismatch << ',' << r->seconds << ",\"" << r->reason << "\"\n";
    };
    for (const auto& r : report.tortuosity) row(r, report.spacing, report.grid.shape);
    for (const auto& r : report.tortuosity_coarse) row(r, report.coarse_spacing, report.coarse_shape);
  }
  std::ofstream summary(in("analysis.txt"));
  summary << "# ellc microstructure analysis (docs/microstructure.md)\n";
  write_analysis_summary(summary, report);
  if (!summary) throw InputError(in("analysis.txt"), "output file", in("analysis.txt"), "a writable path");
}

}  // namespace ellc::microstructure
