#pragma once
// ellc.dem's compiled part (bind_dem.cpp): the scenario runner of `ellc dem` (python/ellc/dem.py).

#include <pybind11/pybind11.h>

namespace ellc::python {

void bind_dem(pybind11::module_& module);

}  // namespace ellc::python
