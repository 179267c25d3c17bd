// Material layer and elliptical Hertz (paper Sec. 2).

#include <pybind11/stl.h>

#include <array>

#include "bindings.hpp"
#include "ellc/hertz/elliptic_hertz.hpp"
#include "ellc/material/material.hpp"
#include "numpy_support.hpp"

namespace ellc::python {

namespace {

std::string material_repr(const Material& material) {
  return "Material(youngs_modulus=" + std::string(py::repr(py::float_(material.youngs_modulus))) +
         ", poisson_ratio=" + std::string(py::repr(py::float_(material.poisson_ratio))) +
         ", yield_stress=" + std::string(py::repr(py::float_(material.yield_stress))) + ")";
}

}  // namespace

void bind_material_and_hertz(py::module_& module) {
  py::class_<Material>(module, "Material",
                       "Isotropic elastic-ideally-plastic material: E (MPa), Poisson's ratio, yield stress Y (MPa).")
      .def(py::init([](double youngs_modulus, double poisson_ratio, double yield_stress) {
             Material material{youngs_modulus, poisson_ratio, yield_stress};
             if (const std::string error = validation_error(material); !error.empty()) throw py::value_error(error);
             return material;
           }),
           py::arg("youngs_modulus"), py::arg("poisson_ratio"), py::arg("yield_stress"))
      .def_readwrite("youngs_modulus", &Material::youngs_modulus)
      .def_readwrite("poisson_ratio", &Material::poisson_ratio)
      .def_readwrite("yield_stress", &Material::yield_stress)
      .def("__repr__", &material_repr);

  py::class_<ContactMaterial>(module, "ContactMaterial",
                              "What a contact needs from two materials: effective modulus E_e (eq. 3) and Y.")
      .def(py::init<>())
      .def(py::init([](double effective_modulus, double yield_stress) {
             return ContactMaterial{effective_modulus, yield_stress};
           }),
           py::arg("effective_modulus"), py::arg("yield_stress"))
      .def_readwrite("effective_modulus", &ContactMaterial::effective_modulus)
      .def_readwrite("yield_stress", &ContactMaterial::yield_stress);

  module.def("effective_modulus", &effective_modulus, py::arg("material_i"), py::arg("material_j"),
             "E_e = [(1 - nu_I^2)/E_I + (1 - nu_J^2)/E_J]^-1, paper eq. (3).");
  module.def("mix", &mix, py::arg("material_i"), py::arg("material_j"),
             "ContactMaterial of two bodies: E_e of eq. (3) and Y = min(Y_I, Y_J) (the softer body yields first).");

  py::class_<PrincipalCurvatures>(module, "PrincipalCurvatures",
                                  "Principal curvatures (1/µm) of one body at the contact point; a wall has 0.")
      .def(py::init([](double kappa_1, double kappa_2) {
             return PrincipalCurvatures{kappa_1, kappa_2};
           }),
           py::arg("kappa_1"), py::arg("kappa_2"))
      .def_readwrite("kappa_1", &PrincipalCurvatures::kappa_1)
      .def_readwrite("kappa_2", &PrincipalCurvatures::kappa_2)
      .def("__repr__", [](const PrincipalCurvatures& c) {
        return "PrincipalCurvatures(kappa_1=" + std::string(py::repr(py::float_(c.kappa_1))) +
               ", kappa_2=" + std::string(py::repr(py::float_(c.kappa_2))) + ")";
      });

  py::class_<RelativeCurvature>(module, "RelativeCurvature", "A and B of eq. (5), B >= A.")
      .def(py::init([](double a_sum, double b_sum) {
             return RelativeCurvature{a_sum, b_sum};
           }),
           py::arg("a_sum"), py::arg("b_sum"))
      .def_readwrite("a_sum", &RelativeCurvature::a_sum)
      .def_readwrite("b_sum", &RelativeCurvature::b_sum);
  module.def("relative_curvature", &relative_curvature, py::arg("body_i"), py::arg("body_j"), py::arg("alpha"),
             "A and B of eq. (5) from both bodies' principal curvatures and the angle alpha (rad) between "
             "their kappa_1 directions.");

  py::class_<HertzShape>(module, "HertzShape", "R_e (eq. 6), e^2 (eq. 7), f1, f2 (eq. 4 or exact).")
      .def(py::init<>())
      .def_readwrite("equivalent_radius", &HertzShape::equivalent_radius)
      .def_readwrite("eccentricity_sq", &HertzShape::eccentricity_sq)
      .def_readwrite("f1", &HertzShape::f1)
      .def_readwrite("f2", &HertzShape::f2)
      .def_property_readonly("contact_radius_sq_per_overlap", &HertzShape::contact_radius_sq_per_overlap,
                             "c_c^2 / delta = R_e f1^2 / f2, eq. (9).");
  module.def(
      "hertz_shape",
      [](const RelativeCurvature& curvature, const std::string& hertz) {
        return hertz_shape(curvature, hertz_mode(hertz));
      },
      py::arg("curvature"), py::arg("hertz") = "hale",
      "Hertz shape for A <= B: Hale's fit (hertz='hale', eq. 4 and 7) or the exact elliptic-integral solution "
      "(hertz='exact').");

  py::class_<HertzContact>(module, "HertzContact", "Contact ellipse, p0 and F_H at one overlap.")
      .def_readonly("semi_axis_major", &HertzContact::semi_axis_major)
      .def_readonly("semi_axis_minor", &HertzContact::semi_axis_minor)
      .def_readonly("equivalent_contact_radius", &HertzContact::equivalent_contact_radius)
      .def_readonly("peak_pressure", &HertzContact::peak_pressure)
      .def_readonly("force", &HertzContact::force);
  module.def("hertz_contact", &hertz_contact, py::arg("shape"), py::arg("effective_modulus"), py::arg("overlap"),
             "a_c, b_c (eq. 8), c_c (eq. 9), p0 (eq. 2) and F_H (eq. 10) at overlap delta >= 0.");
  module.def(
      "hertz_contacts",
      [](const HertzShape& shape, double effective_modulus, const py::handle& overlaps) {
        const DoubleArray overlap_array = vector_argument(overlaps, "overlaps");
        const py::ssize_t size = overlap_array.size();
        std::array<py::array_t<double>, 5> columns{new_vector<double>(size), new_vector<double>(size),
                                                   new_vector<double>(size), new_vector<double>(size),
                                                   new_vector<double>(size)};
        std::array<double*, 5> out{};
        for (std::size_t column = 0; column < out.size(); ++column) out[column] = columns[column].mutable_data();
        {
          py::gil_scoped_release release;
          for (py::ssize_t index = 0; index < size; ++index) {
            const HertzContact contact = hertz_contact(shape, effective_modulus, overlap_array.data()[index]);
            out[0][index] = contact.semi_axis_major;
            out[1][index] = contact.semi_axis_minor;
            out[2][index] = contact.equivalent_contact_radius;
            out[3][index] = contact.peak_pressure;
            out[4][index] = contact.force;
          }
        }
        py::dict result;
        const char* names[] = {"semi_axis_major", "semi_axis_minor", "equivalent_contact_radius", "peak_pressure",
                               "force"};
        for (std::size_t column = 0; column < columns.size(); ++column) result[names[column]] = columns[column];
        return result;
      },
      py::arg("shape"), py::arg("effective_modulus"), py::arg("overlaps"),
      "hertz_contact over a 1-D array of overlaps: a dict of arrays semi_axis_major, semi_axis_minor, "
      "equivalent_contact_radius, peak_pressure, force.");
  module.def(
      "hertz_pressure",
      [](double semi_axis_major, double semi_axis_minor, double peak_pressure, const py::handle& x,
         const py::handle& y) {
        const DoubleArray xs = vector_argument(x, "x");
        const DoubleArray ys = vector_argument(y, "y", xs.size(), "x");
        auto pressures = new_vector<double>(xs.size());
        double* out = pressures.mutable_data();
        {
          py::gil_scoped_release release;
          for (py::ssize_t index = 0; index < xs.size(); ++index)
            out[index] =
                hertz_pressure(semi_axis_major, semi_axis_minor, peak_pressure, xs.data()[index], ys.data()[index]);
        }
        return pressures;
      },
      py::arg("semi_axis_major"), py::arg("semi_axis_minor"), py::arg("peak_pressure"), py::arg("x"), py::arg("y"),
      "Hertz pressure p(x, y) of eq. (1) at the points (x[i], y[i]) (1-D arrays, x along a_c); 0 outside "
      "the ellipse.");
}

}  // namespace ellc::python
