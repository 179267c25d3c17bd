#pragma once
// Synthetic calibration data made by the law itself (known constants), for the calibration tests.

#include <Eigen/Core>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "ellc/calibration/calibration_case.hpp"
#include "ellc/cases/case_file.hpp"
#include "ellc/law/contact_law.hpp"
#include "support/nmc.hpp"

namespace ellc::testing_support {

using ellc::test::kNmc;

// Known constants, deliberately different from the paper's eq. (53).
inline LawParameters true_law() {
  LawParameters law;
  law.fit = {1.3, -3.5, 2.2, 6.5, -5.0, 1.4, 2.2};
  return law;
}

inline BodySpec body(const Eigen::Vector3d& aspect, double mean_radius = 10.0) {
  BodySpec spec;
  spec.semi_axes = aspect * (mean_radius / std::cbrt(aspect.prod()));
  spec.material = kNmc;
  return spec;
}

// Monotonic loading to `reach` δ_max in `points` steps, forces times (1 + noise N(0, 1)).
inline CalibrationCase synthetic_case(const std::string& name, const Eigen::Vector3d& aspect_i,
                                      const Eigen::Vector3d& aspect_j, double noise, unsigned seed,
                                      const LawParameters& law = true_law(), int points = 40, double reach = 1.5) {
  CalibrationCase data;
  data.name = name;
  data.body_i = body(aspect_i);
  data.body_j = body(aspect_j);
  const ContactConstants constants = case_contact_constants(data.body_i, data.body_j, HertzMode::hale, law);
  std::mt19937 generator(seed);
  std::normal_distribution<double> normal;
  for (int step = 1; step <= points; ++step) {
    const double overlap = reach * constants.plastic_limit_overlap * step / points;
    data.overlaps.push_back(overlap);
    data.forces.push_back(loading_force(constants, overlap).force * (1.0 + noise * normal(generator)));
  }
  return data;
}

inline std::vector<CalibrationCase> synthetic_set(double noise, unsigned seed) {
  return {synthetic_case("sphere", {1, 1, 1}, {1, 1, 1}, noise, seed),
          synthetic_case("paper_case2", {1, 1, 0.8}, {1, 1.25, 1.25}, noise, seed + 1),
          synthetic_case("fig10", {1, 0.66, 0.66}, {1, 0.66, 0.66}, noise, seed + 2),
          synthetic_case("flat", {1, 2, 2}, {1, 2, 2}, noise, seed + 3),
          synthetic_case("slim", {1, 0.5, 0.5}, {1, 0.5, 0.5}, noise, seed + 4),
          synthetic_case("mixed", {1, 1.5, 1.5}, {1, 0.8, 0.8}, noise, seed + 5)};
}

}  // namespace ellc::testing_support
