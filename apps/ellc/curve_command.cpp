// `ellc curve CASE.toml [-o out.csv] [--plot out.png] [--hertz hale|exact]`
// A displacement-driven load/unload/reload run of one tip-to-tip contact (paper Sec. 5).

#include <cstdio>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "command_registry.hpp"
#include "ellc/cases/case_file.hpp"
#include "ellc/cases/protocol.hpp"
#include "ellc/geometry/tip_contact.hpp"
#include "ellc/io/input_error.hpp"
#include "ellc/law/contact_patch.hpp"
#include "ellc/law/law_along_path.hpp"
#include "plot_runner.hpp"

namespace ellc::cli {
namespace {

struct CurveOptions {
  std::string case_path;
  std::string csv_path;
  std::string plot_path;
  std::string hertz;
};

// Spheres of the same volume (radius r̂^k) and material as each ellipsoid: the paper's green curve.
BodySpec equal_volume_sphere(const BodySpec& body) {
  BodySpec sphere = body;
  sphere.semi_axes.setConstant(mean_radius(body.semi_axes));
  sphere.twist = 0.0;
  return sphere;
}

std::string axes_text(const Eigen::Vector3d& axes) {
  return "[" + format_number(axes.x()) + ", " + format_number(axes.y()) + ", " + format_number(axes.z()) + "]";
}

// A derived quantity out of range (R_e = -nan) is reported with the fields it came from.
void check(const ContactConstants& constants, const std::string& source, const char* what, const CurveCase& curve) {
  if (const std::string error = validation_error(constants); !error.empty())
    throw InputError(source, "body_I.semi_axes = " + axes_text(curve.body_i.semi_axes) + " and body_J.semi_axes = " +
                                 axes_text(curve.body_j.semi_axes) + " (with [material] and [model]): " + what +
                                 " have contact constants out of range: " + error);
}

std::vector<LawResult> run(const ContactConstants& constants, const std::vector<double>& path) {
  std::vector<LawResult> results(path.size());
  evaluate_along_path(constants, path, results);
  return results;
}

void write_csv(std::ostream& out, const std::vector<double>& path, const ContactConstants& constants,
               const std::vector<LawResult>& results, const std::vector<LawResult>& spheres,
               const std::vector<LawResult>& elastic_fully_plastic) {
  out.precision(17);
  out << "overlap,force,regime,max_overlap,plastic_overlap,contact_semi_axis_major,contact_semi_axis_minor,"
         "peak_pressure,overlap_over_yield,force_over_yield,force_equal_volume_spheres_over_yield,"
         "force_elastic_fully_plastic_over_yield\n";
  for (std::size_t index = 0; index < path.size(); ++index) {
    const LawResult& result = results[index];
    const double previous_max = index == 0 ? 0.0 : results[index - 1].max_overlap;
    const ContactPatch patch = contact_patch(constants, path[index], previous_max);
    out << path[index] << ',' << result.force << ',' << regime_name(result.regime) << ',' << result.max_overlap << ','
        << plastic_overlap(constants, result.max_overlap) << ',' << patch.semi_axis_major << ','
        << patch.semi_axis_minor << ',' << (patch.semi_axis_major > 0.0 ? patch.peak_pressure() : 0.0) << ','
        << path[index] / constants.yield_overlap << ',' << result.force / constants.yield_force << ','
        << spheres[index].force / constants.yield_force << ','
        << elastic_fully_plastic[index].force / constants.yield_force << '\n';
  }
}

void print_summary(std::FILE* out, const CurveCase& curve_case, const ContactConstants& c, HertzMode mode,
                   const std::vector<double>& path, const std::vector<LawResult>& results) {
  std::fprintf(out, "ellc curve: %zu points, Hertz %s\n", path.size(), mode == HertzMode::exact ? "exact" : "hale");
  std::fprintf(out, "  body I semi-axes  %.6g %.6g %.6g µm, body J %.6g %.6g %.6g µm\n",
               curve_case.body_i.semi_axes.x(), curve_case.body_i.semi_axes.y(), curve_case.body_i.semi_axes.z(),
               curve_case.body_j.semi_axes.x(), curve_case.body_j.semi_axes.y(), curve_case.body_j.semi_axes.z());
  std::fprintf(out, "  R_e      = %.6g µm  (eq. 6)\n", c.equivalent_radius);
  std::fprintf(out, "  e        = %.6g     (eq. 7)\n", std::sqrt(c.eccentricity_sq));
  std::fprintf(out, "  f1, f2   = %.6g, %.6g  (eq. 4)\n", c.f1, c.f2);
  std::fprintf(out, "  delta_Y  = %.6g µm  F_pY = %.6g µN  (elastic limit, p0 = %.3g Y)\n", c.yield_overlap,
               c.yield_force, c.yield_pressure_factor);
  std::fprintf(out, "  lambda_max = %.6g  epsilon_max = %.6g  (eq. 52)\n", c.lambda_max, c.epsilon_max);
  std::fprintf(out, "  delta_max  = %.6g µm  (eq. 30)\n", c.plastic_limit_overlap);
  // δ_p at the end of each unloading: a point where the path stops decreasing.
  int unloading_count = 0;
  for (std::size_t index = 1; index < path.size(); ++index) {
    const bool decreasing = path[index] < path[index - 1];
    const bool turns = index + 1 == path.size() || path[index + 1] >= path[index];
    if (!decreasing || !turns) continue;
    const double max_overlap = results[index].max_overlap;
    std::fprintf(out, "  unloading %d: delta_* = %.6g µm -> delta_p = %.6g µm (eq. 34)\n", ++unloading_count,
                 max_overlap, plastic_overlap(c, max_overlap));
  }
}

void run_curve(const CurveOptions& options) {
  CurveCase curve_case = read_curve_case(options.case_path);
  if (!options.hertz.empty()) curve_case.model.hertz = options.hertz == "exact" ? HertzMode::exact : HertzMode::hale;
  for (const auto& warning : curve_case.warnings) std::fprintf(stderr, "ellc: warning: %s\n", warning.c_str());

  const ModelSpec& model = curve_case.model;
  const ContactConstants constants =
      case_contact_constants(curve_case.body_i, curve_case.body_j, model.hertz, model.law);
  const ContactConstants sphere_constants = case_contact_constants(
      equal_volume_sphere(curve_case.body_i), equal_volume_sphere(curve_case.body_j), model.hertz, model.law);
  const ContactConstants efp_constants =
      case_contact_constants(curve_case.body_i, curve_case.body_j, model.hertz, model.law.elastic_fully_plastic());
  check(constants, options.case_path, "the ellipsoid pair", curve_case);
  check(sphere_constants, options.case_path, "the equal-volume spheres", curve_case);

  const std::vector<double> path = protocol_overlaps(curve_case.waypoints, curve_case.points_per_segment);
  const auto results = run(constants, path);
  const auto spheres = run(sphere_constants, path);
  const auto elastic_fully_plastic = run(efp_constants, path);

  std::FILE* summary = options.csv_path.empty() ? stderr : stdout;  // CSV on stdout when no -o
  if (options.csv_path.empty()) {
    write_csv(std::cout, path, constants, results, spheres, elastic_fully_plastic);
  } else {
    std::ofstream file(options.csv_path);
    if (!file) throw InputError(options.csv_path, "cannot open the output file for writing");
    write_csv(file, path, constants, results, spheres, elastic_fully_plastic);
    if (!file) throw std::runtime_error("writing " + options.csv_path + " failed");
  }
  print_summary(summary, curve_case, constants, model.hertz, path, results);

  if (!options.plot_path.empty()) {
    if (options.csv_path.empty())
      throw InputError("", "--plot", options.plot_path, "-o out.csv as well (the plot reads it)");
    run_python_plot({"curve", options.csv_path, options.plot_path, "--title", options.case_path});
    std::fprintf(summary, "  plot: %s\n", options.plot_path.c_str());
  }
  if (!options.csv_path.empty()) std::fprintf(summary, "  csv:  %s\n", options.csv_path.c_str());
}

const RegisterCommand registration([](CLI::App& root) {
  auto options = std::make_shared<CurveOptions>();
  CLI::App* command = root.add_subcommand("curve", "Load/unload/reload one tip-to-tip contact along a protocol");
  command->add_option("case", options->case_path, "Case file (TOML): [material], [body_I], [body_J], [protocol]")
      ->required();
  command->add_option("-o,--output", options->csv_path, "CSV output (default: standard output)");
  command->add_option("--plot", options->plot_path, "PNG of F/F_pY against delta/delta_Y (needs -o)");
  command->add_option("--hertz", options->hertz, "Hertz solution: hale or exact (overrides [model].hertz)")
      ->check(CLI::IsMember({"hale", "exact"}));
  command->callback([options] { run_curve(*options); });
});

}  // namespace
}  // namespace ellc::cli
