// Calibration of the transition fits from force data (paper Sec. 4; docs/calibration.md).

#include <pybind11/stl.h>

#include "bindings.hpp"
#include "ellc/calibration/calibration_output.hpp"
#include "ellc/calibration/transition_calibration.hpp"
#include "numpy_support.hpp"

namespace ellc::python {

namespace {

py::dict profile_arrays(const std::vector<LambdaSample>& samples) {
  const auto size = static_cast<py::ssize_t>(samples.size());
  auto overlap = new_vector<double>(size);
  auto force = new_vector<double>(size);
  auto ratio = new_vector<double>(size);
  auto lambda = new_vector<double>(size);
  auto weight = new_vector<double>(size);
  for (py::ssize_t index = 0; index < size; ++index) {
    const LambdaSample& sample = samples[static_cast<std::size_t>(index)];
    overlap.mutable_data()[index] = sample.overlap;
    force.mutable_data()[index] = sample.force;
    ratio.mutable_data()[index] = sample.contact_radius_ratio;
    lambda.mutable_data()[index] = sample.lambda;
    weight.mutable_data()[index] = sample.weight;
  }
  py::dict arrays;
  arrays["overlap"] = overlap;
  arrays["force"] = force;
  arrays["contact_radius_ratio"] = ratio;
  arrays["lambda"] = lambda;
  arrays["weight"] = weight;
  return arrays;
}

}  // namespace

void bind_calibration(py::module_& module) {
  py::class_<CalibrationCase>(module, "CalibrationCase",
                              "Force against overlap for one known tip-to-tip geometry (µm, µN).")
      .def(py::init([](std::string name, const BodySpec& body_i, const BodySpec& body_j, const py::handle& overlaps,
                       const py::handle& forces) {
             const DoubleArray overlap_array = vector_argument(overlaps, "overlaps");
             const DoubleArray force_array = vector_argument(forces, "forces", overlap_array.size(), "overlaps");
             const auto overlap_view = view(overlap_array);
             const auto force_view = view(force_array);
             return CalibrationCase{std::move(name),
                                    body_i,
                                    body_j,
                                    {overlap_view.begin(), overlap_view.end()},
                                    {force_view.begin(), force_view.end()}};
           }),
           py::arg("name"), py::arg("body_i"), py::arg("body_j"), py::arg("overlaps"), py::arg("forces"))
      .def_readonly("name", &CalibrationCase::name)
      .def_readonly("body_i", &CalibrationCase::body_i)
      .def_readonly("body_j", &CalibrationCase::body_j)
      .def_property_readonly("overlaps",
                             [](const CalibrationCase& c) {
                               return py::array_t<double>(static_cast<py::ssize_t>(c.overlaps.size()),
                                                          c.overlaps.data());
                             })
      .def_property_readonly("forces", [](const CalibrationCase& c) {
        return py::array_t<double>(static_cast<py::ssize_t>(c.forces.size()), c.forces.data());
      });
  module.def(
      "read_calibration_case",
      [](const std::string& data, const std::optional<std::string>& case_path) {
        return case_path ? read_calibration_case(data, *case_path) : read_calibration_case(data);
      },
      py::arg("data"), py::arg("case") = py::none(),
      "Reads a CSV with columns overlap, force and its case file (given, or found as `ellc fit` does).");

  py::class_<TransitionPoint>(module, "TransitionPoint", "lambda_max, epsilon_max and n of one case (eq. 28).")
      .def(py::init([](double lambda_max, double epsilon_max, double n) {
             return TransitionPoint{lambda_max, epsilon_max, n};
           }),
           py::arg("lambda_max"), py::arg("epsilon_max"), py::arg("n"))
      .def_readwrite("lambda_max", &TransitionPoint::lambda_max)
      .def_readwrite("epsilon_max", &TransitionPoint::epsilon_max)
      .def_readwrite("n", &TransitionPoint::exponent)
      .def("__repr__", [](const TransitionPoint& p) {
        return py::str("TransitionPoint(lambda_max={!r}, epsilon_max={!r}, n={!r})")
            .format(p.lambda_max, p.epsilon_max, p.exponent);
      });
  module.def(
      "profile_lambda",
      [](const TransitionPoint& point, const py::handle& ratios, double yield_pressure_factor) {
        const DoubleArray values = vector_argument(ratios, "contact_radius_ratio");
        auto out = new_vector<double>(values.size());
        double* lambdas = out.mutable_data();
        {
          py::gil_scoped_release release;
          for (py::ssize_t index = 0; index < values.size(); ++index)
            lambdas[index] = profile_lambda(point, values.data()[index], yield_pressure_factor);
        }
        return out;
      },
      py::arg("point"), py::arg("contact_radius_ratio"), py::arg("yield_pressure_factor") = 1.6,
      "Eq. (28) against c_c/c_Y (lambda_max beyond epsilon_max).");
  module.def(
      "lambda_profile",
      [](const ContactConstants& constants, const py::handle& overlaps, const py::handle& forces) {
        const DoubleArray overlap_array = vector_argument(overlaps, "overlaps");
        const DoubleArray force_array = vector_argument(forces, "forces", overlap_array.size(), "overlaps");
        std::vector<LambdaSample> samples;
        {
          py::gil_scoped_release release;
          samples = lambda_profile(constants, view(overlap_array), view(force_array));
        }
        return profile_arrays(samples);
      },
      py::arg("constants"), py::arg("overlaps"), py::arg("forces"),
      "lambda_FEM of eq. (51) on the virgin-loading points beyond delta_Y: a dict of arrays overlap, force, "
      "contact_radius_ratio (c_c/c_Y), lambda, weight.");

  py::class_<CaseCalibration>(module, "CaseCalibration", "The calibration of one case.")
      .def_readonly("name", &CaseCalibration::name)
      .def_readonly("radius_ratio", &CaseCalibration::radius_ratio, "R_e / r^{I,J}.")
      .def_readonly("equivalent_radius", &CaseCalibration::equivalent_radius)
      .def_readonly("yield_overlap", &CaseCalibration::yield_overlap)
      .def_readonly("yield_force", &CaseCalibration::yield_force)
      .def_property_readonly(
          "profile", [](const CaseCalibration& c) { return profile_arrays(c.profile); },
          "lambda_FEM points (eq. 51) as a dict of numpy arrays.")
      .def_readonly("own", &CaseCalibration::own, "lambda_max, epsilon_max, n fitted to this case alone.")
      .def_readonly("shared", &CaseCalibration::shared, "lambda_max, epsilon_max with the n shared by all cases.")
      .def_readonly("own_rms", &CaseCalibration::own_rms)
      .def_readonly("shared_rms", &CaseCalibration::shared_rms)
      .def_readonly("model_rms", &CaseCalibration::model_rms,
                    "RMS relative force error of the calibrated law (eq. 52 constants) on this case.")
      .def_readonly("plateau_reached", &CaseCalibration::plateau_reached)
      .def("__repr__",
           [](const CaseCalibration& c) {
             return py::str(
                        "CaseCalibration(name={!r}, radius_ratio={:.4g}, lambda_max={:.4g}, epsilon_max={:.4g}, "
                        "n={:.4g}, plateau_reached={}, model_rms={:.3g})")
                 .format(c.name, c.radius_ratio, c.shared.lambda_max, c.shared.epsilon_max, c.shared.exponent,
                         c.plateau_reached, c.model_rms);
           })
      .def_readonly("transition_found", &CaseCalibration::transition_found,
                    "False when lambda_FEM never rises from 1.6 (epsilon_max on its lower bound): a run the law "
                    "cannot describe; see the warnings.");

  py::class_<CalibrationResult>(module, "CalibrationResult", "Result of ellc.calibrate.")
      .def_readonly("cases", &CalibrationResult::cases)
      .def_readonly("law", &CalibrationResult::law, "The calibrated LawParameters (ready for Contact.between).")
      .def_property_readonly("fit", [](const CalibrationResult& r) { return r.law.fit; })
      .def_property_readonly("hertz", [](const CalibrationResult& r) { return std::string(hertz_name(r.hertz)); })
      .def_readonly("rates_fitted", &CalibrationResult::rates_fitted)
      .def_readonly("amplitudes_fitted", &CalibrationResult::amplitudes_fitted)
      .def_readonly("warnings", &CalibrationResult::warnings)
      .def("__repr__",
           [](const CalibrationResult& r) {
             return py::str("CalibrationResult({} cases, fit={!r}, {} warnings)")
                 .format(r.cases.size(), py::cast(r.law.fit), r.warnings.size());
           })
      .def("model_toml", &model_table_toml, "The [model] table for `ellc curve` / `ellc dem`, as TOML text.")
      .def(
          "write_tables",
          [](const CalibrationResult& result, const std::string& prefix, const LawParameters& prior) {
            return write_calibration_tables(result, prior, prefix);
          },
          py::arg("prefix"), py::arg("prior") = LawParameters{},
          "Writes PREFIX_lambda.csv, PREFIX_cases.csv, PREFIX_radius.csv as `ellc fit --plot` does.");

  module.def(
      "calibrate",
      [](const std::vector<CalibrationCase>& cases, const std::string& hertz, const LawParameters& prior,
         double elastic_tolerance, std::size_t min_plastic_points) {
        CalibrationOptions options;
        options.hertz = hertz_mode(hertz);
        options.prior = prior;
        options.elastic_tolerance = elastic_tolerance;
        options.min_plastic_points = min_plastic_points;
        py::gil_scoped_release release;
        return calibrate(cases, options);
      },
      py::arg("cases"), py::arg("hertz") = "hale", py::arg("prior") = LawParameters{},
      py::arg("elastic_tolerance") = 0.02, py::arg("min_plastic_points") = 4,
      "Fits lambda_max, epsilon_max, n per case (eq. 51, 28), one shared n, and m, o, p, s, t, u of eq. (52) "
      "across cases, as `ellc fit` does. Raises ellc.InputError (a ValueError) for unusable data, e.g. data "
      "that never leaves the elastic regime.");
}

}  // namespace ellc::python
