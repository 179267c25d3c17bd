// ellc._ellc: the Becker–Kamlah contact law, Hertz and geometry layers of libellc for Python.
// Names follow the C++ library in snake_case; docs/python.md is the guide.

#include "bind_dem.hpp"
#include "bindings.hpp"

#include "ellc/io/input_error.hpp"

namespace ellc::python {

HertzMode hertz_mode(const std::string& name) {
  if (name == "hale") return HertzMode::hale;
  if (name == "exact") return HertzMode::exact;
  throw py::value_error("hertz = '" + name + "': expected 'hale' or 'exact'");
}

const char* hertz_name(HertzMode mode) { return mode == HertzMode::exact ? "exact" : "hale"; }

}  // namespace ellc::python

PYBIND11_MODULE(_ellc, module) {
  namespace py = pybind11;
  module.doc() =
      "Normal contact force between elastoplastic ellipsoids (Becker & Kamlah): materials, elliptical "
      "Hertz, tip-to-tip and general ellipsoid contact geometry, the contact law with vectorized "
      "evaluation along overlap paths, and the calibration of its transition fits. Units as in the "
      "C++ library: µm, MPa, µN.";
  // Bad input files and bad calibration data: a ValueError subclass with the file and field named.
  static py::exception<ellc::InputError> input_error(module, "InputError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr pointer) {
    try {
      if (pointer) std::rethrow_exception(pointer);
    } catch (const ellc::InputError& error) {
      input_error(error.what());
    }
  });
  ellc::python::bind_material_and_hertz(module);
  // Order matters: default arguments (e.g. law=LawParameters()) need their types registered first.
  ellc::python::bind_law(module);
  ellc::python::bind_cases(module);
  ellc::python::bind_geometry(module);
  ellc::python::bind_dem(module);
  ellc::python::bind_microstructure(module);  // the submodule ellc._ellc.microstructure
#ifdef ELLC_PYTHON_CALIBRATION
  ellc::python::bind_calibration(module);
#endif
}
