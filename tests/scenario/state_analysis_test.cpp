// states_summary: the lines `ellc dem` appends to summary.txt must keep that file a TOML
// document also when τ_z does not percolate (inf and a prose reason) and when no state gives a
// Bruggeman exponent.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <toml++/toml.h>

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

}  // namespace
