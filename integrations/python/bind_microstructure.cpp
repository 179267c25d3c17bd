// ellc._ellc.microstructure: the microstructure of a packing (docs/microstructure.md). Packings
// come in as numpy arrays (centres and semi-axes n×3, quaternions n×4 as (w, x, y, z)); voxel grids
// go out as uint8 arrays indexed [iz, iy, ix], the layout of the .npy files.

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <limits>
#include <sstream>
#include <string>

#include "bindings.hpp"
#include "ellc/microstructure/analysis.hpp"
#include "ellc/microstructure/packing.hpp"
#include "ellc/microstructure/tortuosity.hpp"
#include "ellc/microstructure/voxel_grid.hpp"

namespace ellc::python {

namespace {

using microstructure::Packing;
using Rows = py::array_t<double, py::array::c_style | py::array::forcecast>;

Rows rows_argument(const py::handle& value, const char* name, py::ssize_t columns) {
  Rows array = Rows::ensure(value);
  if (!array || array.ndim() != 2 || array.shape(1) != columns)
    throw py::value_error(std::string(name) + ": expected an array of shape (n, " + std::to_string(columns) + ")");
  return array;
}

Packing make_packing(const py::handle& centres, const py::handle& semi_axes, const py::handle& quaternions,
                     const Eigen::Vector3d& box_lower, const Eigen::Vector3d& box_upper,
                     const std::array<bool, 3>& periodic) {
  const Rows c = rows_argument(centres, "centres", 3);
  const Rows s = rows_argument(semi_axes, "semi_axes", 3);
  const Rows q = rows_argument(quaternions, "quaternions", 4);
  if (s.shape(0) != c.shape(0) || q.shape(0) != c.shape(0))
    throw py::value_error("centres, semi_axes and quaternions: expected the same number of rows, got " +
                          std::to_string(c.shape(0)) + ", " + std::to_string(s.shape(0)) + ", " +
                          std::to_string(q.shape(0)));
  Packing packing;
  const auto cv = c.unchecked<2>();
  const auto sv = s.unchecked<2>();
  const auto qv = q.unchecked<2>();
  for (py::ssize_t k = 0; k < c.shape(0); ++k) {
    packing.centres.emplace_back(cv(k, 0), cv(k, 1), cv(k, 2));
    packing.semi_axes.emplace_back(sv(k, 0), sv(k, 1), sv(k, 2));
    packing.orientations.emplace_back(qv(k, 0), qv(k, 1), qv(k, 2), qv(k, 3));
  }
  packing.box.lower = box_lower;
  packing.box.upper = box_upper;
  packing.box.periodic = periodic;
  microstructure::validate_packing(packing, "Packing");
  return packing;
}

microstructure::Resolution resolution_of(double voxels_per_semi_axis, double spacing, double memory_limit_gib) {
  microstructure::Resolution resolution;
  resolution.voxels_per_semi_axis = voxels_per_semi_axis;
  resolution.spacing = spacing;
  resolution.memory_limit_bytes = memory_limit_gib * 1024.0 * 1024.0 * 1024.0;
  return resolution;
}

py::array_t<std::uint8_t> grid_array(const microstructure::VoxelGrid& grid) {
  py::array_t<std::uint8_t> array({grid.shape[2], grid.shape[1], grid.shape[0]});
  std::copy(grid.solid.begin(), grid.solid.end(), array.mutable_data());
  return array;
}

py::dict diffusion_dict(const microstructure::DiffusionResult& r) {
  py::dict d;
  d["axis"] = r.axis;
  d["percolating"] = r.percolating;
  d["reason"] = r.reason;
  d["porosity"] = r.porosity;
  d["conducting_fraction"] = r.conducting_fraction;
  d["effective_diffusivity"] = r.effective_diffusivity;
  d["tortuosity"] = r.tortuosity;
  d["flux_mismatch"] = r.flux_mismatch;
  d["iterations"] = r.iterations;
  d["converged"] = r.converged;
  return d;
}

}  // namespace

void bind_microstructure(py::module_& parent) {
  py::module_ module = parent.def_submodule(
      "microstructure", "Voxels, porosity profiles, pore sizes, tortuosity and force network of a packing.");
  py::class_<Packing>(module, "Packing",
                      "Ellipsoids (centres, semi-axes, quaternions (w, x, y, z)) in a box with periodic flags.")
      .def(py::init(&make_packing), py::arg("centres"), py::arg("semi_axes"), py::arg("quaternions"),
           py::arg("box_lower"), py::arg("box_upper"), py::arg("periodic") = std::array<bool, 3>{true, true, false})
      .def("__len__", &Packing::size)
      .def_property_readonly("particle_volume", &Packing::particle_volume)
      .def_property_readonly("smallest_semi_axis", &Packing::smallest_semi_axis);
  module.def("read_packing", &microstructure::read_packing_file, py::arg("path"),
             "A packing file (CSV, docs/microstructure.md); InputError names the bad row.");
  module.def("write_packing", &microstructure::write_packing_file, py::arg("path"), py::arg("packing"));
  module.def(
      "voxelise",
      [](const Packing& packing, double voxels_per_semi_axis, double spacing, double memory_limit_gib) {
        microstructure::VoxelGrid grid;
        {
          py::gil_scoped_release release;
          grid = microstructure::voxelise(packing, resolution_of(voxels_per_semi_axis, spacing, memory_limit_gib));
        }
        return py::make_tuple(grid_array(grid), grid.spacing);
      },
      py::arg("packing"), py::arg("voxels_per_semi_axis") = 5.0, py::arg("spacing") = 0.0,
      py::arg("memory_limit_gib") = 4.0,
      "(solid, spacing): solid as uint8 [iz, iy, ix] (1 = solid), spacing per axis (µm).");
  module.def(
      "tortuosity",
      [](const Packing& packing, int axis, double voxels_per_semi_axis, double spacing, double memory_limit_gib) {
        if (axis < 0 || axis > 2) throw py::value_error("axis = " + std::to_string(axis) + ": expected 0, 1 or 2");
        microstructure::DiffusionResult result;
        {
          py::gil_scoped_release release;
          const auto grid =
              microstructure::voxelise(packing, resolution_of(voxels_per_semi_axis, spacing, memory_limit_gib));
          result = microstructure::tortuosity_factor(grid, axis);
        }
        return diffusion_dict(result);
      },
      py::arg("packing"), py::arg("axis") = 2, py::arg("voxels_per_semi_axis") = 5.0, py::arg("spacing") = 0.0,
      py::arg("memory_limit_gib") = 4.0,
      "Tortuosity factor tau = porosity D_bulk / D_eff of the pore phase along axis (0 x, 1 y, 2 z); "
      "tortuosity = inf and the reason when no pore path percolates.");
  module.def(
      "tortuosity_of_grid",
      [](const py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>& solid,
         const Eigen::Vector3d& spacing, const std::array<bool, 3>& periodic, int axis) {
        if (solid.ndim() != 3) throw py::value_error("solid: expected a 3-D array [iz, iy, ix]");
        if (axis < 0 || axis > 2) throw py::value_error("axis = " + std::to_string(axis) + ": expected 0, 1 or 2");
        microstructure::VoxelGrid grid;
        grid.shape = {static_cast<int>(solid.shape(2)), static_cast<int>(solid.shape(1)),
                      static_cast<int>(solid.shape(0))};
        grid.spacing = spacing;
        grid.periodic = periodic;
        grid.solid.assign(solid.data(), solid.data() + solid.size());
        microstructure::DiffusionResult result;
        {
          py::gil_scoped_release release;
          result = microstructure::tortuosity_factor(grid, axis);
        }
        return diffusion_dict(result);
      },
      py::arg("solid"), py::arg("spacing") = Eigen::Vector3d::Ones(),
      py::arg("periodic") = std::array<bool, 3>{false, false, false}, py::arg("axis") = 2,
      "The tortuosity factor of any voxel image (uint8 [iz, iy, ix], non-zero = solid).");
  module.def(
      "analyse",
      [](const Packing& packing, const std::string& directory, double voxels_per_semi_axis, double spacing,
         double memory_limit_gib, double coarse_factor) {
        microstructure::AnalysisOptions options;
        options.resolution = resolution_of(voxels_per_semi_axis, spacing, memory_limit_gib);
        options.coarse_factor = coarse_factor;
        std::ostringstream summary;
        {
          py::gil_scoped_release release;
          const auto report = microstructure::analyse(packing, options);
          if (!directory.empty()) microstructure::write_analysis(directory, packing, report);
          microstructure::write_analysis_summary(summary, report);
        }
        return summary.str();  // a TOML document: ellc.microstructure.analyse reads it with tomllib
      },
      py::arg("packing"), py::arg("directory") = "", py::arg("voxels_per_semi_axis") = 5.0, py::arg("spacing") = 0.0,
      py::arg("memory_limit_gib") = 4.0, py::arg("coarse_factor") = 2.0,
      "The analysis of `ellc analyse`; writes its files into `directory` unless empty; returns analysis.txt's TOML "
      "text.");
  module.def(
      "extrapolated_tortuosity",
      [](double at_spacing, double at_coarse, double factor) {
        const auto estimate = microstructure::extrapolated_tortuosity(at_spacing, at_coarse, factor);
        return estimate ? *estimate : std::numeric_limits<double>::quiet_NaN();
      },
      py::arg("at_spacing"), py::arg("at_coarse"), py::arg("factor") = 2.0,
      "tau extrapolated to zero voxel size from tau at h and at factor * h (first order, Richardson); with tau(h) "
      "it brackets the converged value where tau falls with a shrinking slope. NaN unless both are finite.");
  module.def("fit_bruggeman_exponent", &microstructure::fit_bruggeman_exponent, py::arg("porosity"),
             py::arg("tortuosity"), "alpha of D_eff/D = porosity^alpha (tau = porosity^(1 - alpha)); NaN if none.");
}

}  // namespace ellc::python
