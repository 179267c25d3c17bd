// Paper case 2 through the installed headers and libellc only, compared with `ellc curve`.
//
//   paper_case2 CURVE.csv [CASE.toml]
//
// CURVE.csv is the output of `ellc curve examples/paper_case2.toml -o CURVE.csv`. The constants
// are built here from the case's numbers, as apps/ellc/curve_command.cpp builds them from the case
// file: NMC (E = 142000 MPa, nu = 0.25, Y = 7900 MPa), body I aspect 1:1:0.8, body J 1:1.25:1.25,
// both of mean radius 10 um, tip to tip along x, Hale's Hertz fit, the paper's transition fit.
// At a sample of rows (every regime the path visits) the force and regime of
// evaluate_contact(constants, overlap, delta_* of the row before) must equal the CSV's to 1e-12
// relative. With CASE.toml, the constants read through ellc::read_curve_case must match too (this
// also links the toml++ part of libellc). Exit status 0 when everything matches.

#include <ellc/cases/case_file.hpp>
#include <ellc/geometry/tip_contact.hpp>
#include <ellc/law/contact_constants.hpp>
#include <ellc/law/contact_law.hpp>
#include <ellc/material/material.hpp>

#include <Eigen/Core>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

namespace {

constexpr double kTolerance = 1e-12;

// Semi-axes of aspect [1, b/a, c/a] scaled to the mean radius (abc)^(1/3) = r (paper eq. 50).
Eigen::Vector3d semi_axes(const Eigen::Vector3d& aspect, double mean_radius) {
  return aspect * (mean_radius / std::cbrt(aspect.prod()));
}

ellc::ContactConstants paper_case2_constants() {
  const ellc::Material nmc{142000.0, 0.25, 7900.0};
  const Eigen::Vector3d axes_i = semi_axes({1.0, 1.0, 0.8}, 10.0);
  const Eigen::Vector3d axes_j = semi_axes({1.0, 1.25, 1.25}, 10.0);
  const ellc::TipContact tip = ellc::tip_contact({axes_i, 0.0}, {axes_j, 0.0});
  return ellc::make_contact_constants(ellc::mix(nmc, nmc), tip.body_i, tip.body_j, tip.alpha,
                                      ellc::mean_radius(axes_i) + ellc::mean_radius(axes_j),
                                      ellc::HertzMode::hale, ellc::LawParameters{});
}

bool close(double value, double reference) {
  if (reference == 0.0) return value == 0.0;
  return std::abs(value - reference) <= kTolerance * std::abs(reference);
}

struct Row {
  double overlap = 0.0;
  double force = 0.0;
  std::string regime;
  double max_overlap = 0.0;
};

std::vector<Row> read_curve_csv(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  if (!std::getline(in, line) || line.rfind("overlap,force,regime,max_overlap,", 0) != 0) {
    std::fprintf(stderr, "%s: not an `ellc curve` CSV (header: %s)\n", path.c_str(), line.c_str());
    return {};
  }
  std::vector<Row> rows;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string overlap, force, regime, max_overlap;
    std::getline(fields, overlap, ',');
    std::getline(fields, force, ',');
    std::getline(fields, regime, ',');
    std::getline(fields, max_overlap, ',');
    rows.push_back({std::stod(overlap), std::stod(force), regime, std::stod(max_overlap)});
  }
  return rows;
}

int compare_with_case_file(const ellc::ContactConstants& expected, const std::string& path) {
  const ellc::CurveCase curve_case = ellc::read_curve_case(path);
  const ellc::ContactConstants read = ellc::case_contact_constants(
      curve_case.body_i, curve_case.body_j, curve_case.model.hertz, curve_case.model.law);
  int failures = 0;
  for (const auto& [name, value, reference] :
       {std::tuple{"yield_overlap", read.yield_overlap, expected.yield_overlap},
        std::tuple{"yield_force", read.yield_force, expected.yield_force},
        std::tuple{"equivalent_radius", read.equivalent_radius, expected.equivalent_radius},
        std::tuple{"plastic_limit_overlap", read.plastic_limit_overlap, expected.plastic_limit_overlap}}) {
    if (!close(value, reference)) {
      std::fprintf(stderr, "%s: %s = %.17g, from the numbers %.17g\n", path.c_str(), name, value, reference);
      ++failures;
    }
  }
  return failures;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || argc > 3) {
    std::fprintf(stderr, "usage: paper_case2 CURVE.csv [CASE.toml]\n");
    return 2;
  }
  const ellc::ContactConstants constants = paper_case2_constants();
  const std::vector<Row> rows = read_curve_csv(argv[1]);
  if (rows.size() < 2) return 1;

  int failures = 0;
  std::map<std::string, int> checked;  // regime -> rows compared
  for (std::size_t index = 0; index < rows.size(); ++index) {
    const bool regime_changes = index > 0 && rows[index].regime != rows[index - 1].regime;
    if (index % 25 != 0 && !regime_changes && index + 1 != rows.size()) continue;
    const double history = index == 0 ? 0.0 : rows[index - 1].max_overlap;
    const ellc::LawResult result = ellc::evaluate_contact(constants, rows[index].overlap, history);
    const std::string regime = ellc::regime_name(result.regime);
    if (!close(result.force, rows[index].force) || regime != rows[index].regime) {
      std::fprintf(stderr, "row %zu: overlap %.17g: force %.17g (%s), ellc curve %.17g (%s)\n", index,
                   rows[index].overlap, result.force, regime.c_str(), rows[index].force, rows[index].regime.c_str());
      ++failures;
    }
    ++checked[rows[index].regime];
  }
  if (argc == 3) failures += compare_with_case_file(constants, argv[2]);

  std::printf("paper case 2: delta_Y = %.6g um, F_pY = %.6g uN; rows compared:", constants.yield_overlap,
              constants.yield_force);
  for (const auto& [regime, count] : checked) std::printf(" %s %d", regime.c_str(), count);
  std::printf("; %s\n", failures == 0 ? "all equal to 1e-12" : "MISMATCH");
  return failures == 0 ? 0 : 1;
}
