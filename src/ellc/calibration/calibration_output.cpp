#include "ellc/calibration/calibration_output.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <limits>
#include <stdexcept>

namespace ellc {

namespace {

std::ofstream open_table(const std::string& path, std::vector<std::string>& written) {
  std::ofstream file(path);
  if (!file) throw std::runtime_error("cannot open " + path + " for writing");
  file.precision(12);
  written.push_back(path);
  return file;
}

TransitionPoint model_point(const LawParameters& law, double radius_ratio) {
  return {law.fit.lambda_max(radius_ratio), law.fit.epsilon_max(radius_ratio), law.fit.transition_exponent};
}

}  // namespace

std::vector<std::string> write_calibration_tables(const CalibrationResult& result, const LawParameters& prior,
                                                  const std::string& prefix) {
  std::vector<std::string> written;
  const double factor = result.law.yield_pressure_factor;
  if (const auto folder = std::filesystem::path(prefix).parent_path(); !folder.empty())
    std::filesystem::create_directories(folder);
  {
    std::ofstream file = open_table(prefix + "_lambda.csv", written);
    file << "case,overlap,overlap_over_yield,contact_radius_ratio,force,lambda_data,lambda_case_fit,"
            "lambda_shared_fit,lambda_model\n";
    for (const auto& entry : result.cases) {
      const TransitionPoint model = model_point(result.law, entry.radius_ratio);
      for (const auto& sample : entry.profile)
        file << entry.name << ',' << sample.overlap << ',' << sample.overlap / entry.yield_overlap << ','
             << sample.contact_radius_ratio << ',' << sample.force << ',' << sample.lambda << ','
             << profile_lambda(entry.own, sample.contact_radius_ratio, factor) << ','
             << profile_lambda(entry.shared, sample.contact_radius_ratio, factor) << ','
             << profile_lambda(model, sample.contact_radius_ratio, factor) << '\n';
    }
    if (!file) throw std::runtime_error("writing " + prefix + "_lambda.csv failed");
  }
  {
    std::ofstream file = open_table(prefix + "_cases.csv", written);
    file << "case,radius_ratio,lambda_max,epsilon_max,n,lambda_max_own,epsilon_max_own,n_own,plateau_reached,"
            "rms_own,rms_shared,rms_model\n";
    for (const auto& entry : result.cases)
      file << entry.name << ',' << entry.radius_ratio << ',' << entry.shared.lambda_max << ','
           << entry.shared.epsilon_max << ',' << entry.shared.exponent << ',' << entry.own.lambda_max << ','
           << entry.own.epsilon_max << ',' << entry.own.exponent << ',' << (entry.plateau_reached ? 1 : 0) << ','
           << entry.own_rms << ',' << entry.shared_rms << ',' << entry.model_rms << '\n';
    if (!file) throw std::runtime_error("writing " + prefix + "_cases.csv failed");
  }
  {
    std::ofstream file = open_table(prefix + "_radius.csv", written);
    file << "radius_ratio,lambda_max_fit,epsilon_max_fit,lambda_max_prior,epsilon_max_prior\n";
    // The cases' range of R_e/r̂ and a margin on both sides: eq. (52) is an extrapolation beyond.
    double largest = 0.0;
    double smallest = std::numeric_limits<double>::infinity();
    for (const auto& entry : result.cases) {
      largest = std::max(largest, entry.radius_ratio);
      smallest = std::min(smallest, entry.radius_ratio);
    }
    const double start = 0.5 * smallest;
    const double end = 1.25 * largest;
    constexpr int kSteps = 200;
    for (int step = 0; step <= kSteps; ++step) {
      const double x = start + (end - start) * step / kSteps;
      file << x << ',' << result.law.fit.lambda_max(x) << ',' << result.law.fit.epsilon_max(x) << ','
           << prior.fit.lambda_max(x) << ',' << prior.fit.epsilon_max(x) << '\n';
    }
    if (!file) throw std::runtime_error("writing " + prefix + "_radius.csv failed");
  }
  return written;
}

}  // namespace ellc
