#pragma once
// Tables behind the calibration plots (paper Fig. 11 and 12), written next to the [model] TOML.

#include <string>
#include <vector>

#include "ellc/calibration/transition_calibration.hpp"

namespace ellc {

// Writes PREFIX_lambda.csv (λ profile points and fits per case, Fig. 11), PREFIX_cases.csv (one
// row per case) and PREFIX_radius.csv (eq. 52 curves against R_e/r̂, Fig. 12, with the prior's
// curves for comparison). Returns the paths; throws std::runtime_error when a file cannot be written.
std::vector<std::string> write_calibration_tables(const CalibrationResult& result, const LawParameters& prior,
                                                  const std::string& prefix);

}  // namespace ellc
