// Contact geometry: the paper's tip-to-tip configuration (Sec. 5).

#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "ellc/geometry/tip_contact.hpp"

namespace ellc::python {

void bind_geometry(py::module_& module) {
  py::class_<TipBody>(module, "TipBody",
                      "An ellipsoid with semi-axis a along the line of centres x, touching at its x tip, twisted "
                      "about x by `twist` radians.")
      .def(py::init([](const Eigen::Vector3d& semi_axes, double twist) { return TipBody{semi_axes, twist}; }),
           py::arg("semi_axes"), py::arg("twist") = 0.0)
      .def_readwrite("semi_axes", &TipBody::semi_axes)
      .def_readwrite("twist", &TipBody::twist);

  py::class_<TipContact>(module, "TipContact", "Principal curvatures of both bodies at the tips and the angle alpha.")
      .def_readonly("body_i", &TipContact::body_i)
      .def_readonly("body_j", &TipContact::body_j)
      .def_readonly("alpha", &TipContact::alpha);

  module.def("mean_radius", &mean_radius, py::arg("semi_axes"), "r^k = (a b c)^(1/3), eq. (50).");
  module.def("tip_curvatures", &tip_curvatures, py::arg("semi_axes"), "Curvatures at the x tip: (a/b^2, a/c^2).");
  module.def("tip_contact", &tip_contact, py::arg("body_i"), py::arg("body_j"),
             "Curvatures and alpha of two bodies touching at their x tips.");
}

}  // namespace ellc::python
