// The contact law (paper Sec. 3): constants, scalar evaluation, and ellc.Contact with vectorized
// evaluation along overlap paths (GIL released while the loops run).

#include <pybind11/stl.h>

#include <cmath>
#include <limits>
#include <vector>

#include "bindings.hpp"
#include "ellc/cases/case_file.hpp"
#include "ellc/law/contact_constants.hpp"
#include "ellc/law/contact_law.hpp"
#include "ellc/law/contact_patch.hpp"
#include "ellc/law/law_along_path.hpp"
#include "ellc/law/transition_fit.hpp"
#include "numpy_support.hpp"

namespace ellc::python {

namespace {

struct Contact {
  ContactConstants constants;
};

// Arrays along a path; the history δ_* is returned so a path can be continued.
struct PathResult {
  py::array force;
  py::array max_overlap;
  py::array plastic_overlap;
  py::array regime;
};

struct PatchArrays {
  py::array semi_axis_major;
  py::array semi_axis_minor;
  py::array field_peak_pressure;
  py::array pressure_cap;
  py::array peak_pressure;
};

PathResult evaluate_along_path_arrays(const Contact& contact, const py::handle& overlaps_in,
                                      double initial_max_overlap) {
  const DoubleArray overlaps = vector_argument(overlaps_in, "overlaps");
  const py::ssize_t size = overlaps.size();
  auto force = new_vector<double>(size);
  auto max_overlap = new_vector<double>(size);
  auto plastic = new_vector<double>(size);
  auto regime = new_vector<std::uint8_t>(size);
  double* force_out = force.mutable_data();
  double* max_out = max_overlap.mutable_data();
  double* plastic_out = plastic.mutable_data();
  std::uint8_t* regime_out = regime.mutable_data();
  {
    py::gil_scoped_release release;
    std::vector<LawResult> results(static_cast<std::size_t>(size));
    evaluate_along_path(contact.constants, view(overlaps), results, initial_max_overlap);
    for (std::size_t index = 0; index < results.size(); ++index) {
      force_out[index] = results[index].force;
      max_out[index] = results[index].max_overlap;
      plastic_out[index] = plastic_overlap(contact.constants, results[index].max_overlap);
      regime_out[index] = static_cast<std::uint8_t>(results[index].regime);
    }
  }
  return {force, max_overlap, plastic, regime};
}

PatchArrays patch_arrays(const Contact& contact, const py::handle& overlaps_in, double initial_max_overlap) {
  const DoubleArray overlaps = vector_argument(overlaps_in, "overlaps");
  const py::ssize_t size = overlaps.size();
  auto major = new_vector<double>(size);
  auto minor = new_vector<double>(size);
  auto field = new_vector<double>(size);
  auto cap = new_vector<double>(size);
  auto peak = new_vector<double>(size);
  double* outputs[] = {major.mutable_data(), minor.mutable_data(), field.mutable_data(), cap.mutable_data(),
                       peak.mutable_data()};
  {
    py::gil_scoped_release release;
    double max_overlap = initial_max_overlap;
    for (py::ssize_t index = 0; index < size; ++index) {
      const double overlap = overlaps.data()[index];
      const ContactPatch patch = contact_patch(contact.constants, overlap, max_overlap);
      outputs[0][index] = patch.semi_axis_major;
      outputs[1][index] = patch.semi_axis_minor;
      outputs[2][index] = patch.field_peak_pressure;
      outputs[3][index] = patch.pressure_cap;
      outputs[4][index] = patch.semi_axis_major > 0.0 ? patch.peak_pressure() : 0.0;
      max_overlap = evaluate_contact(contact.constants, overlap, max_overlap).max_overlap;
    }
  }
  return {major, minor, field, cap, peak};
}

// Elementwise map of a scalar function of δ over a 1-D array, GIL released.
template <typename Function>
py::array map_overlaps(const py::handle& overlaps_in, Function function) {
  const DoubleArray overlaps = vector_argument(overlaps_in, "overlaps");
  auto out = new_vector<double>(overlaps.size());
  double* values = out.mutable_data();
  {
    py::gil_scoped_release release;
    for (py::ssize_t index = 0; index < overlaps.size(); ++index) values[index] = function(overlaps.data()[index]);
  }
  return out;
}

}  // namespace

void bind_law(py::module_& module) {
  py::class_<TransitionFit>(module, "TransitionFit",
                            "Transition fits of eq. (52): lambda_max = m exp(o x) + p, epsilon_max = s exp(t x) + u "
                            "with x = R_e / r^{I,J}, and the exponent n of eq. (28). Defaults: eq. (53), n = 1.8.")
      .def(py::init([](double m, double o, double p, double s, double t, double u, double n) {
             return TransitionFit{m, o, p, s, t, u, n};
           }),
           py::arg("m") = 1.05, py::arg("o") = -4.62, py::arg("p") = 2.42, py::arg("s") = 8.19, py::arg("t") = -6.14,
           py::arg("u") = 1.14, py::arg("n") = 1.8)
      .def_readwrite("m", &TransitionFit::lambda_amplitude)
      .def_readwrite("o", &TransitionFit::lambda_rate)
      .def_readwrite("p", &TransitionFit::lambda_offset)
      .def_readwrite("s", &TransitionFit::epsilon_amplitude)
      .def_readwrite("t", &TransitionFit::epsilon_rate)
      .def_readwrite("u", &TransitionFit::epsilon_offset)
      .def_readwrite("n", &TransitionFit::transition_exponent)
      .def("lambda_max", py::vectorize(&TransitionFit::lambda_max), py::arg("radius_ratio"),
           "lambda_max(R_e/r^), eq. (52); accepts a number or an array.")
      .def("epsilon_max", py::vectorize(&TransitionFit::epsilon_max), py::arg("radius_ratio"),
           "epsilon_max(R_e/r^), eq. (52); accepts a number or an array.")
      .def(
          "as_dict",
          [](const TransitionFit& f) {
            py::dict d;
            d["m"] = f.lambda_amplitude, d["o"] = f.lambda_rate, d["p"] = f.lambda_offset;
            d["s"] = f.epsilon_amplitude, d["t"] = f.epsilon_rate, d["u"] = f.epsilon_offset;
            d["n"] = f.transition_exponent;
            return d;
          },
          "The constants keyed like the [model] table: m, o, p, s, t, u, n.")
      .def("__repr__", [](const TransitionFit& f) {
        return py::str("TransitionFit(m={!r}, o={!r}, p={!r}, s={!r}, t={!r}, u={!r}, n={!r})")
            .format(f.lambda_amplitude, f.lambda_rate, f.lambda_offset, f.epsilon_amplitude, f.epsilon_rate,
                    f.epsilon_offset, f.transition_exponent);
      });

  py::class_<LawParameters>(module, "LawParameters", "The law's parameters: the transition fit and p_Y / Y (1.6).")
      .def(py::init([](const TransitionFit& fit, double yield_pressure_factor) {
             LawParameters law{fit, yield_pressure_factor};
             if (const std::string error = validation_error(law); !error.empty()) throw py::value_error(error);
             return law;
           }),
           py::arg("fit") = TransitionFit{}, py::arg("yield_pressure_factor") = 1.6)
      .def_readwrite("fit", &LawParameters::fit)
      .def_readwrite("yield_pressure_factor", &LawParameters::yield_pressure_factor)
      .def("elastic_fully_plastic", &LawParameters::elastic_fully_plastic,
           "Thornton's elastic-fully-plastic variant (lambda = 1.6 throughout), the thin line of Fig. 6.");

  py::class_<ContactConstants>(module, "ContactConstants",
                               "Everything about one contact that does not depend on the overlap (read-only).")
      .def_readonly("effective_modulus", &ContactConstants::effective_modulus)
      .def_readonly("yield_stress", &ContactConstants::yield_stress)
      .def_readonly("equivalent_radius", &ContactConstants::equivalent_radius)
      .def_readonly("eccentricity_sq", &ContactConstants::eccentricity_sq)
      .def_readonly("f1", &ContactConstants::f1)
      .def_readonly("f2", &ContactConstants::f2)
      .def_readonly("contact_radius_sq_per_overlap", &ContactConstants::contact_radius_sq_per_overlap)
      .def_readonly("hertz_coefficient", &ContactConstants::hertz_coefficient)
      .def_readonly("yield_pressure", &ContactConstants::yield_pressure)
      .def_readonly("yield_contact_radius", &ContactConstants::yield_contact_radius)
      .def_readonly("yield_overlap", &ContactConstants::yield_overlap)
      .def_readonly("yield_force", &ContactConstants::yield_force)
      .def_readonly("lambda_max", &ContactConstants::lambda_max)
      .def_readonly("epsilon_max", &ContactConstants::epsilon_max)
      .def_readonly("transition_exponent", &ContactConstants::transition_exponent)
      .def_readonly("yield_pressure_factor", &ContactConstants::yield_pressure_factor)
      .def_readonly("plastic_limit_overlap", &ContactConstants::plastic_limit_overlap)
      .def(
          "validation_error", [](const ContactConstants& c) { return validation_error(c); },
          "Empty string when the law can be evaluated with these constants, else the reason.")
      .def("__repr__", [](const ContactConstants& c) {
        return py::str(
                   "ContactConstants(equivalent_radius={:.6g}, yield_overlap={:.6g}, yield_force={:.6g}, "
                   "lambda_max={:.6g}, epsilon_max={:.6g}, plastic_limit_overlap={:.6g})")
            .format(c.equivalent_radius, c.yield_overlap, c.yield_force, c.lambda_max, c.epsilon_max,
                    c.plastic_limit_overlap);
      });

  module.def(
      "make_contact_constants",
      [](const ContactMaterial& material, const PrincipalCurvatures& body_i, const PrincipalCurvatures& body_j,
         double alpha, double mean_radius_sum, const std::string& hertz, const LawParameters& law) {
        return make_contact_constants(material, body_i, body_j, alpha, mean_radius_sum, hertz_mode(hertz), law);
      },
      py::arg("material"), py::arg("body_i"), py::arg("body_j"), py::arg("alpha"), py::arg("mean_radius_sum"),
      py::arg("hertz") = "hale", py::arg("law") = LawParameters{},
      "Contact constants from the principal curvatures of both bodies, the angle alpha between their kappa_1 "
      "directions and r^{I,J} = r^I + r^J (eq. 50).");

  py::enum_<Regime>(module, "Regime", "Where on the law a point lies.")
      .value("SEPARATED", Regime::separated)
      .value("ELASTIC", Regime::elastic)
      .value("ELASTIC_PLASTIC", Regime::elastic_plastic)
      .value("FULLY_PLASTIC", Regime::fully_plastic)
      .value("UNLOADING", Regime::unloading);
  module.def(
      "regime_name", [](int code) { return regime_name(static_cast<Regime>(code)); }, py::arg("code"),
      "The name `ellc curve` writes for a regime code (e.g. 'elastic_plastic').");

  py::class_<LawResult>(module, "LawResult")
      .def_readonly("force", &LawResult::force)
      .def_readonly("max_overlap", &LawResult::max_overlap)
      .def_readonly("regime", &LawResult::regime);
  module.def("evaluate_contact", &evaluate_contact, py::arg("constants"), py::arg("overlap"),
             py::arg("max_overlap") = 0.0,
             "The law at one overlap given the history max_overlap (delta_*); returns force, new delta_*, regime.");

  py::class_<UnloadingBranch>(module, "UnloadingBranch",
                              "The unloading branch derived from a history delta_* > delta_Y.")
      .def_readonly("loading_force", &UnloadingBranch::loading_force)
      .def_readonly("fully_plastic_force", &UnloadingBranch::fully_plastic_force)
      .def_readonly("hertz_force", &UnloadingBranch::hertz_force)
      .def_readonly("plastic_radius", &UnloadingBranch::plastic_radius)
      .def_readonly("plastic_overlap", &UnloadingBranch::plastic_overlap)
      .def_readonly("force_ratio", &UnloadingBranch::force_ratio)
      .def_readonly("unloading_radius", &UnloadingBranch::unloading_radius)
      .def_readonly("unloading_coefficient", &UnloadingBranch::unloading_coefficient);
  module.def("unloading_branch", &unloading_branch, py::arg("constants"), py::arg("max_overlap"),
             "R_e,p (eq. 44), delta_p (eq. 34), beta (eq. 46), R_e,pmax (eq. 48) for history delta_*.");
  module.def("transition_lambda", &transition_lambda, py::arg("constants"), py::arg("contact_radius"),
             "lambda of eq. (28) at equivalent contact radius c_c in [c_Y, c_max].");

  py::class_<ContactPatch>(module, "ContactPatch", "Contact ellipse and pressure at one point of the history.")
      .def_readonly("semi_axis_major", &ContactPatch::semi_axis_major)
      .def_readonly("semi_axis_minor", &ContactPatch::semi_axis_minor)
      .def_readonly("field_peak_pressure", &ContactPatch::field_peak_pressure)
      .def_readonly("pressure_cap", &ContactPatch::pressure_cap)
      .def_property_readonly("peak_pressure", &ContactPatch::peak_pressure);
  module.def("contact_patch", &contact_patch, py::arg("constants"), py::arg("overlap"), py::arg("max_overlap") = 0.0,
             "Hertz ellipse while elastic, Hertz truncated at lambda Y while loading plastically, Hertz with "
             "R_e,pmax about delta_p while unloading (Fig. 4, 9, 14).");

  py::class_<PathResult>(module, "PathResult", "The law along an overlap path: numpy arrays, one entry per overlap.")
      .def_readonly("force", &PathResult::force, "Normal force (µN).")
      .def_readonly("max_overlap", &PathResult::max_overlap, "History delta_* after each point.")
      .def_readonly("plastic_overlap", &PathResult::plastic_overlap,
                    "delta_p of eq. (34) for that history (0 if elastic).")
      .def_readonly("regime", &PathResult::regime, "Regime codes (uint8, ellc.Regime values).");
  py::class_<PatchArrays>(module, "PatchArrays", "Contact patches along an overlap path: numpy arrays.")
      .def_readonly("semi_axis_major", &PatchArrays::semi_axis_major)
      .def_readonly("semi_axis_minor", &PatchArrays::semi_axis_minor)
      .def_readonly("field_peak_pressure", &PatchArrays::field_peak_pressure)
      .def_readonly("pressure_cap", &PatchArrays::pressure_cap, "Plateau pressure lambda Y; inf when not truncated.")
      .def_readonly("peak_pressure", &PatchArrays::peak_pressure, "min(field peak, cap); 0 when separated.");

  py::class_<Contact>(module, "Contact",
                      "One contact: its constants and vectorized evaluation of the law. Build it with "
                      "Contact(constants), Contact.between(body_i, body_j) or Contact.from_case(case).")
      .def(py::init([](const ContactConstants& constants) {
             if (const std::string error = validation_error(constants); !error.empty()) throw py::value_error(error);
             return Contact{constants};
           }),
           py::arg("constants"))
      .def_static(
          "between",
          [](const BodySpec& body_i, const BodySpec& body_j, const std::string& hertz, const LawParameters& law) {
            const ContactConstants constants = case_contact_constants(body_i, body_j, hertz_mode(hertz), law);
            if (const std::string error = validation_error(constants); !error.empty()) throw py::value_error(error);
            return Contact{constants};
          },
          py::arg("body_i"), py::arg("body_j"), py::arg("hertz") = "hale", py::arg("law") = LawParameters{},
          "The tip-to-tip contact of two bodies (paper Sec. 5), as `ellc curve` builds it.")
      .def_static(
          "from_case",
          [](const CurveCase& curve_case) {
            const ContactConstants constants = case_contact_constants(curve_case.body_i, curve_case.body_j,
                                                                      curve_case.model.hertz, curve_case.model.law);
            if (const std::string error = validation_error(constants); !error.empty()) throw py::value_error(error);
            return Contact{constants};
          },
          py::arg("case"), "The contact of a case file read by read_curve_case (its [model] applies).")
      .def_readonly("constants", &Contact::constants)
      .def("__repr__",
           [](const Contact& contact) { return "Contact(" + std::string(py::repr(py::cast(contact.constants))) + ")"; })
      // Python keeps the name evaluate_path; in C++ it is evaluate_along_path (ellc/law/law_along_path.hpp).
      .def("evaluate_path", &evaluate_along_path_arrays, py::arg("overlaps"), py::arg("initial_max_overlap") = 0.0,
           "The law along a 1-D array of overlaps, carrying delta_* from point to point (history kept through "
           "delta <= 0, as `ellc curve` does). Returns a PathResult; its max_overlap[-1] continues the path.")
      .def(
          "force",
          [](const Contact& contact, const py::handle& overlaps, double initial_max_overlap) {
            return evaluate_along_path_arrays(contact, overlaps, initial_max_overlap).force;
          },
          py::arg("overlaps"), py::arg("initial_max_overlap") = 0.0, "evaluate_path(...).force.")
      .def(
          "loading_force",
          [](const Contact& contact, const py::handle& overlaps) {
            return map_overlaps(overlaps, [&](double d) { return loading_force(contact.constants, d).force; });
          },
          py::arg("overlaps"), "The loading envelope F(delta) for monotonic loading (eq. 10, 25, 31).")
      .def(
          "lambda_profile",
          [](const Contact& contact, const py::handle& overlaps) {
            const ContactConstants& c = contact.constants;
            return map_overlaps(overlaps, [&](double d) {
              if (!(d > c.yield_overlap)) return std::numeric_limits<double>::quiet_NaN();
              return transition_lambda(c, std::sqrt(c.contact_radius_sq_per_overlap * d));
            });
          },
          py::arg("overlaps"), "lambda of eq. (28) on loading (lambda_max beyond delta_max); NaN for delta <= delta_Y.")
      .def("patches", &patch_arrays, py::arg("overlaps"), py::arg("initial_max_overlap") = 0.0,
           "Contact ellipse and pressure along the path (see contact_patch).")
      .def(
          "patch",
          [](const Contact& contact, double overlap, double max_overlap) {
            return contact_patch(contact.constants, overlap, max_overlap);
          },
          py::arg("overlap"), py::arg("max_overlap") = 0.0, "contact_patch at one point.")
      .def(
          "unloading_branch",
          [](const Contact& contact, double max_overlap) { return unloading_branch(contact.constants, max_overlap); },
          py::arg("max_overlap"));
}

}  // namespace ellc::python
