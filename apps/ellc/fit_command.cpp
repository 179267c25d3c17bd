// `ellc fit DATA... [-o model.toml] [--plot PREFIX] [--hertz hale|exact] [--prior FILE]`
// Calibrates λ_max, ε_max, n per case and m, o, p, s, t, u across cases (paper Sec. 4,
// eq. 51, 28, 52) from force–overlap data; docs/calibration.md describes DATA.

#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "command_registry.hpp"
#include "ellc/calibration/calibration_output.hpp"
#include "ellc/calibration/transition_calibration.hpp"
#include "ellc/cases/case_file.hpp"
#include "ellc/io/input_error.hpp"
#include "ellc/io/table_reader.hpp"
#include "plot_runner.hpp"

namespace ellc::cli {
namespace {

struct FitOptions {
  std::vector<std::string> data;
  std::string output_path;
  std::string plot_prefix;
  std::string hertz = "hale";
  std::string prior_path;
  double elastic_tolerance = 0.02;
  std::string form = "paper";  // paper: one material; stiffness_ratio: several, λ_max, ε_max × (E_e/Y)^q
};

// The [model] table of a TOML file (a previous fit or a case file) as the prior.
ModelSpec read_prior(const std::string& path) {
  const toml::table root_table = parse_toml_file(path);
  TableReader root(root_table, "", path);
  auto model = root.optional_table("model");
  if (!model) throw InputError(path, "no [model] table: expected the prior's m, o, p, s, t, u, n there");
  return read_model(*model);
}

void run_fit(const FitOptions& options) {
  CalibrationOptions calibration;
  if (!options.prior_path.empty()) {
    const ModelSpec prior = read_prior(options.prior_path);
    calibration.prior = prior.law;
  }
  calibration.hertz = options.hertz == "exact" ? HertzMode::exact : HertzMode::hale;
  calibration.elastic_tolerance = options.elastic_tolerance;
  calibration.form = options.form == "stiffness_ratio" ? TransitionForm::stiffness_ratio : TransitionForm::paper;

  std::vector<CalibrationCase> cases;
  for (const auto& argument : options.data) cases.push_back(read_calibration_case(argument));
  const CalibrationResult result = calibrate(cases, calibration);
  const std::string table = model_table_toml(result);

  std::FILE* summary = options.output_path.empty() ? stderr : stdout;  // TOML on stdout when no -o
  if (options.output_path.empty()) {
    std::cout << table;
  } else {
    std::ofstream file(options.output_path);
    if (!file) throw InputError(options.output_path, "cannot open the output file for writing");
    file << table;
    if (!file) throw std::runtime_error("writing " + options.output_path + " failed");
  }
  std::fprintf(summary, "ellc fit: %zu case(s), Hertz %s\n", result.cases.size(), options.hertz.c_str());
  std::fprintf(summary, "  %-24s %8s %10s %11s %8s %8s\n", "case", "R_e/r^", "lambda_max", "epsilon_max", "plateau",
               "rms");
  for (const auto& entry : result.cases)
    std::fprintf(summary, "  %-24s %8.4g %10.4g %11.4g %8s %7.3g%%\n", entry.name.c_str(), entry.radius_ratio,
                 entry.shared.lambda_max, entry.shared.epsilon_max, entry.plateau_reached ? "yes" : "no",
                 100.0 * entry.model_rms);
  const auto& fit = result.law.fit;
  std::fprintf(summary, "  m, o, p = %.4g, %.4g, %.4g   s, t, u = %.4g, %.4g, %.4g   n = %.4g  (eq. 52, 28)\n",
               fit.lambda_amplitude, fit.lambda_rate, fit.lambda_offset, fit.epsilon_amplitude, fit.epsilon_rate,
               fit.epsilon_offset, fit.transition_exponent);
  if (result.stiffness_fitted)
    std::fprintf(summary, "  x (E_e/Y / %.4g)^q: q_lambda = %.4g, q_epsilon = %.4g  (form stiffness_ratio)\n",
                 fit.reference_stiffness_ratio, fit.lambda_stiffness_exponent, fit.epsilon_stiffness_exponent);
  for (const auto& warning : result.warnings) std::fprintf(stderr, "ellc: warning: %s\n", warning.c_str());

  if (!options.plot_prefix.empty()) {
    for (const auto& path : write_calibration_tables(result, calibration.prior, options.plot_prefix))
      std::fprintf(summary, "  table: %s\n", path.c_str());
    run_python_plot({"fit", options.plot_prefix});
    std::fprintf(summary, "  plots: %s_lambda.png (Fig. 11), %s_radius.png (Fig. 12)\n", options.plot_prefix.c_str(),
                 options.plot_prefix.c_str());
  }
  if (!options.output_path.empty()) std::fprintf(summary, "  model: %s\n", options.output_path.c_str());
}

const RegisterCommand registration([](CLI::App& root) {
  auto options = std::make_shared<FitOptions>();
  CLI::App* command = root.add_subcommand(
      "fit", "Calibrate lambda_max, epsilon_max, n and eq. (52) m,o,p,s,t,u from force-overlap data");
  command
      ->add_option("data", options->data,
                   "CSV with columns overlap,force (µm, µN); geometry from CSV.toml next to it, a '# case = X.toml' "
                   "line, or CSV:CASE.toml")
      ->required();
  command->add_option("-o,--output", options->output_path, "TOML with the [model] table (default: standard output)");
  command->add_option("--plot", options->plot_prefix,
                      "Write PREFIX_{lambda,cases,radius}.csv and PREFIX_lambda.png, PREFIX_radius.png");
  command->add_option("--hertz", options->hertz, "Hertz solution used for the fit and written to [model]")
      ->check(CLI::IsMember({"hale", "exact"}));
  command->add_option("--prior", options->prior_path,
                      "TOML with a [model] table: yield_pressure_factor, and constants kept with too few cases "
                      "(default: the paper's eq. 53)");
  command
      ->add_option("--elastic-tolerance", options->elastic_tolerance,
                   "A case whose force beyond delta_Y stays within this RMS fraction of Hertz is elastic (rejected)")
      ->check(CLI::PositiveNumber);
  command
      ->add_option("--form", options->form,
                   "paper: eq. (52), one material; stiffness_ratio: several materials, lambda_max and epsilon_max "
                   "also scale with (E_e/Y)^q (docs/calibration.md)")
      ->check(CLI::IsMember({"paper", "stiffness_ratio"}));
  command->callback([options] { run_fit(*options); });
});

}  // namespace
}  // namespace ellc::cli
