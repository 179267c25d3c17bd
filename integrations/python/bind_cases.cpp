// Case files shared with `ellc curve` and the FE pipeline: bodies, [model], protocols.

#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "ellc/cases/case_file.hpp"
#include "ellc/cases/protocol.hpp"
#include "ellc/geometry/tip_contact.hpp"
#include "numpy_support.hpp"

namespace ellc::python {

void bind_cases(py::module_& module) {
  py::class_<BodySpec>(module, "Body",
                       "One body of a tip-to-tip case: semi-axes (a, b, c) with a along the line of centres x, a "
                       "twist about x (radians) and its material.")
      .def(py::init([](const Eigen::Vector3d& semi_axes, const Material& material, double twist) {
             if (!(semi_axes.minCoeff() > 0.0) || !semi_axes.allFinite())
               throw py::value_error("semi_axes: expected three finite numbers > 0");
             return BodySpec{semi_axes, twist, material};
           }),
           py::arg("semi_axes"), py::arg("material"), py::arg("twist") = 0.0)
      .def_readwrite("semi_axes", &BodySpec::semi_axes)
      .def_readwrite("twist", &BodySpec::twist)
      .def_readwrite("material", &BodySpec::material)
      .def_property_readonly(
          "mean_radius", [](const BodySpec& body) { return mean_radius(body.semi_axes); },
          "r^ = (a b c)^(1/3), eq. (50).");

  py::class_<ModelSpec>(module, "Model", "The [model] table: Hertz solution and law parameters.")
      .def(py::init([](const std::string& hertz, const LawParameters& law) {
             return ModelSpec{hertz_mode(hertz), law};
           }),
           py::arg("hertz") = "hale", py::arg("law") = LawParameters{})
      .def_property(
          "hertz", [](const ModelSpec& model) { return std::string(hertz_name(model.hertz)); },
          [](ModelSpec& model, const std::string& hertz) { model.hertz = hertz_mode(hertz); })
      .def_readwrite("law", &ModelSpec::law);

  py::class_<CurveCase>(module, "CurveCase", "A case file as `ellc curve` reads it.")
      .def_readwrite("body_i", &CurveCase::body_i)
      .def_readwrite("body_j", &CurveCase::body_j)
      .def_readwrite("waypoints", &CurveCase::waypoints)
      .def_readwrite("points_per_segment", &CurveCase::points_per_segment)
      .def_readwrite("model", &CurveCase::model)
      .def_readonly("warnings", &CurveCase::warnings)
      // Python keeps the name overlap_path; in C++ it is protocol_overlaps (ellc/cases/protocol.hpp).
      .def(
          "overlap_path",
          [](const CurveCase& curve_case) {
            const std::vector<double> path = protocol_overlaps(curve_case.waypoints, curve_case.points_per_segment);
            return py::array_t<double>(static_cast<py::ssize_t>(path.size()), path.data());
          },
          "The protocol's overlap path, exactly as `ellc curve` samples it (numpy array).");

  module.def("read_curve_case", &read_curve_case, py::arg("path"),
             "Reads and validates a case file; raises ellc.InputError (a ValueError) naming the field.");
  module.def(
      "parse_curve_case",
      [](const std::string& text, const std::string& source) { return parse_curve_case(text, source); },
      py::arg("text"), py::arg("source") = "<string>", "read_curve_case from TOML text.");
  module.def(
      "overlap_path",
      [](const std::vector<double>& waypoints, long points_per_segment) {
        if (points_per_segment < 1) throw py::value_error("points_per_segment: expected an integer >= 1");
        const std::vector<double> path = protocol_overlaps(waypoints, points_per_segment);
        return py::array_t<double>(static_cast<py::ssize_t>(path.size()), path.data());
      },
      py::arg("waypoints"), py::arg("points_per_segment"),
      "Path through the waypoints, each segment sampled uniformly (numpy array).");
  module.def(
      "case_contact_constants",
      [](const BodySpec& body_i, const BodySpec& body_j, const std::string& hertz, const LawParameters& law) {
        return case_contact_constants(body_i, body_j, hertz_mode(hertz), law);
      },
      py::arg("body_i"), py::arg("body_j"), py::arg("hertz") = "hale", py::arg("law") = LawParameters{},
      "Constants of two bodies touching tip to tip (paper Sec. 5), the builder `ellc curve` uses.");
}

}  // namespace ellc::python
