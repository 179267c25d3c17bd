// Fuzz target: the force-overlap table of `ellc fit` (calibration/calibration_case.hpp). Bytes →
// CSV → validated CalibrationCase for the spheres of paper case 1 → the λ profile of eq. (51),
// the fit's first step.

#include <cstdint>

#include "ellc/calibration/calibration_case.hpp"
#include "ellc/calibration/transition_calibration.hpp"
#include "ellc/io/input_error.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace ellc;
  BodySpec sphere;
  sphere.semi_axes = Eigen::Vector3d::Constant(10.0);
  sphere.material.youngs_modulus = 142000.0;
  sphere.material.poisson_ratio = 0.25;
  sphere.material.yield_stress = 7900.0;
  try {
    const CalibrationCase data_case =
        parse_calibration_case(fuzz::text_of(data, size), "fuzz.csv", sphere, sphere, "spheres.toml");
    const ContactConstants constants = case_contact_constants(data_case.body_i, data_case.body_j, HertzMode::hale, {});
    for (const LambdaSample& sample : lambda_profile(constants, data_case.overlaps, data_case.forces)) {
      fuzz::require_finite(sample.lambda, "non-finite lambda_FEM from a validated table");
      fuzz::require_finite(sample.weight, "non-finite weight from a validated table");
    }
  } catch (const InputError&) {
  }
  return 0;
}
