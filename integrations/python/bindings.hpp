#pragma once
// The pieces of the `ellc._ellc` extension module; each file binds one library layer.

#include <pybind11/pybind11.h>

#include <string>

#include "ellc/hertz/elliptic_hertz.hpp"

namespace ellc::python {

namespace py = pybind11;

// "hale" / "exact" (the spelling of the [model] hertz key) → HertzMode; ValueError otherwise.
HertzMode hertz_mode(const std::string& name);
const char* hertz_name(HertzMode mode);

void bind_material_and_hertz(py::module_& module);
void bind_geometry(py::module_& module);
void bind_law(py::module_& module);
void bind_cases(py::module_& module);
void bind_calibration(py::module_& module);
void bind_microstructure(py::module_& module);

}  // namespace ellc::python
