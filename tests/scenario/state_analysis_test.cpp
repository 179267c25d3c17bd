// summary.txt is a TOML document: write_summary_lines gives every real number exactly and as a
// float, and states_summary (the lines `ellc dem` appends) keeps it TOML also when τ_z does not
// percolate (inf and a prose reason) and when no state gives a Bruggeman exponent.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "ellc/microstructure/tortuosity.hpp"
#include "ellc/scenario/run_outputs.hpp"
#include "ellc/scenario/state_analysis.hpp"

namespace {

using namespace ellc;

scenario::StateAnalysis state(const std::string& name, double porosity, double tortuosity, const std::string& reason) {
  scenario::StateAnalysis result;
  result.state = name;
  result.report.porosity_voxels = porosity;
  microstructure::DiffusionResult tau;
  tau.tortuosity = tortuosity;
  tau.percolating = std::isfinite(tortuosity);
  tau.reason = reason;
  result.report.tortuosity[2] = tau;
  result.report.tortuosity_coarse[2] = tau;
  result.report.spacing = 0.5;
  result.report.coarse_spacing = 1.0;
  return result;
}

toml::table parsed(const std::string& text) {
  try {
    return toml::parse(text);
  } catch (const toml::parse_error& error) {
    ADD_FAILURE() << error.description() << " at line " << error.source().begin.line << " of\n" << text;
    return {};
  }
}

TEST(StatesSummary, NonPercolatingStatesAndNoExponentStayTomlOfTheRightTypes) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const std::string reason = "no pore path connects the faces z = min and z = max (\"closed\")";
  const std::string text =
      scenario::states_summary({state("loaded", 0.25, kInf, reason), state("released", 0.3, kInf, reason)});
  const toml::table table = parsed(text);
  EXPECT_EQ(table["analysis_loaded_tortuosity_z_note"].value<std::string>(), reason);
  EXPECT_TRUE(std::isinf(table["analysis_loaded_tortuosity_z"].value<double>().value_or(0.0)));
  EXPECT_TRUE(std::isinf(table["analysis_released_tortuosity_z_coarse"].value<double>().value_or(0.0)));
  EXPECT_TRUE(std::isnan(table["analysis_bruggeman_exponent"].value<double>().value_or(0.0)));
  EXPECT_DOUBLE_EQ(table["analysis_released_porosity"].value<double>().value_or(0.0), 0.3);
}

TEST(StatesSummary, FiniteTortuositiesGiveAFiniteExponent) {
  const toml::table table =
      parsed(scenario::states_summary({state("loaded", 0.25, 2.0, ""), state("released", 0.36, 1.5, "")}));
  EXPECT_TRUE(table["analysis_bruggeman_exponent"].is_floating_point());
  EXPECT_TRUE(std::isfinite(table["analysis_bruggeman_exponent"].value<double>().value_or(NAN)));
  EXPECT_FALSE(table.contains("analysis_loaded_tortuosity_z_note"));
}

// Where every state has its line to zero voxel size, the exponent is fitted on the lines too: each
// τ lies between its line and τ(h), so α lies between the two exponents; a state without a line
// (a coarse grid under 2.5 voxels per semi-axis) leaves the second exponent out.
TEST(StatesSummary, ExtrapolatedTortuositiesGiveTheExponentsBracket) {
  auto loaded = state("loaded", 0.3465, 2.082, "");
  auto released = state("released", 0.3763, 1.969, "");
  loaded.report.tortuosity_extrapolated[2].tortuosity = 1.656;
  released.report.tortuosity_extrapolated[2].tortuosity = 1.594;
  const toml::table table = parsed(scenario::states_summary({loaded, released}));
  const double at_h = table["analysis_bruggeman_exponent"].value<double>().value_or(NAN);
  const double on_lines = table["analysis_bruggeman_exponent_extrapolated"].value<double>().value_or(NAN);
  EXPECT_DOUBLE_EQ(on_lines, microstructure::fit_bruggeman_exponent({0.3465, 0.3763}, {1.656, 1.594}));
  EXPECT_LT(on_lines, at_h);
  EXPECT_DOUBLE_EQ(table["analysis_loaded_tortuosity_z_extrapolated"].value<double>().value_or(NAN), 1.656);
  released.report.tortuosity_extrapolated[2] = {std::nullopt, "not extrapolated: the coarse grid has 1 voxel"};
  const toml::table partial = parsed(scenario::states_summary({loaded, released}));
  EXPECT_FALSE(partial.contains("analysis_bruggeman_exponent_extrapolated"));
  EXPECT_EQ(partial["analysis_released_tortuosity_z_extrapolated_note"].value<std::string>(),
            "not extrapolated: the coarse grid has 1 voxel");
}

// Real numbers round-trip bit for bit and stay floats when they look like integers (a plate at
// rest: 0; a held pressure of 300), or are not finite; counts stay integers.
TEST(RunSummaryFile, RealsAreExactFloatsAndCountsIntegers) {
  scenario::RunSummary summary;
  summary.finished = true;
  summary.particles = 100;
  summary.steps = 84389;
  summary.held_pressure = 300.0;
  summary.loaded_thickness = 0.1 + 83.74;  // 17 significant digits to keep
  summary.plastic_dissipation = 2987.5912345678901;
  summary.plate_work = 96923.2;
  summary.released_plate_speed = 0.0;
  summary.released_unbalanced_force_ratio = std::numeric_limits<double>::quiet_NaN();
  summary.loaded_validity.pair_contacts = 231;
  std::ostringstream out;
  scenario::write_summary_lines(out, "quick.toml", summary);
  const toml::table table = parsed(out.str());
  for (const char* key : {"held_pressure_MPa", "released_plate_speed_um_per_us", "loaded_thickness_um",
                          "plastic_share_of_plate_work", "released_unbalanced_force_ratio", "validity_threshold"})
    EXPECT_TRUE(table[key].is_floating_point()) << key;
  EXPECT_EQ(table["loaded_thickness_um"].value<double>(), summary.loaded_thickness);
  EXPECT_EQ(table["plastic_share_of_plate_work"].value<double>(), summary.plastic_share_of_plate_work());
  EXPECT_EQ(table["held_pressure_MPa"].value<double>(), 300.0);
  EXPECT_TRUE(std::isnan(table["released_unbalanced_force_ratio"].value<double>().value_or(0.0)));
  for (const char* key : {"particles", "steps", "narrow_phase_failures", "loaded_pair_contacts"})
    EXPECT_TRUE(table[key].is_integer()) << key;
  EXPECT_EQ(table["steps"].value<std::int64_t>(), 84389);
  EXPECT_EQ(table["finished"].value<bool>(), true);
  EXPECT_EQ(table["validity_r_hat"].value<std::string>(), "smaller_particle_of_the_pair");
}

}  // namespace
