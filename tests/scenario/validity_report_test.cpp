// The validity of the loaded state in the summary (the contacts beyond c_c/r̂ = 0.16 and the
// force they carry, at the end of the hold) and the contacts' VTK frames.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <toml++/toml.h>

#include "scenario_support.hpp"

namespace ellc::scenario {
namespace {

using engine::kTopWall;
using engine::ValidityReport;
using testing::in_memory;
using testing::quick_scenario;
using testing::quick_scenario_text;
using testing::replace_line;

std::string temporary(const std::string& name) {
  return (std::filesystem::temp_directory_path() / (name + "_" + std::to_string(::getpid()))).string();
}

// The quick example: the summary's loaded state is the validity report when the hold ended, and
// at 200 MPa nearly all of the plate force rests on wall contacts beyond 0.16 (the wall's R_e is
// the particle's own, larger than a pair's): the CLI's warning says so.
TEST(ScenarioValidity, LoadedStateIsTheValidityReportAtTheEndOfTheHold) {
  ScenarioRunner runner(quick_scenario(quick_scenario_text()), in_memory(512));
  while (!runner.done() && runner.state().phase != Phase::hold) runner.advance(20);
  ASSERT_EQ(runner.state().phase, Phase::hold);
  EXPECT_FALSE(runner.summary().loaded_state_recorded);
  EXPECT_TRUE(summary_warnings(runner.summary()).empty());
  while (runner.state().phase == Phase::hold) {
    const ValidityReport before = runner.simulation().validity(kValidityThreshold);
    const double unbalanced = runner.simulation().unbalanced_force_ratio();
    runner.advance(1);
    if (runner.state().phase != Phase::hold) {  // the hold ended after the step just taken
      const ValidityReport at_end = runner.simulation().validity(kValidityThreshold);
      EXPECT_EQ(runner.loaded_state().validity.pair_force, at_end.pair_force);
      EXPECT_NE(at_end.pair_force, before.pair_force);
      EXPECT_NE(runner.loaded_state().unbalanced_force_ratio, unbalanced);
    }
  }
  runner.advance(200'000);
  ASSERT_TRUE(runner.done());
  const RunSummary summary = runner.summary();
  ASSERT_TRUE(summary.loaded_state_recorded);
  const ValidityReport& v = summary.loaded_validity;
  EXPECT_EQ(v.threshold, 0.16);
  EXPECT_GT(v.pair_contacts, 100U);
  EXPECT_GT(v.wall_contacts, 10U);
  EXPECT_GT(v.largest_ratio, 0.16);
  const ValidityShares& share = summary.loaded_validity_shares;
  EXPECT_NEAR(share.pair_contacts, static_cast<double>(v.pair_contacts_beyond) / static_cast<double>(v.pair_contacts),
              1e-15);
  EXPECT_NEAR(share.wall_force, v.wall_force_beyond / v.wall_force, 1e-15);
  for (double value : {share.pair_contacts, share.pair_force, share.wall_contacts, share.wall_force}) {
    EXPECT_GE(value, 0.0);
    EXPECT_LE(value, 1.0);
  }
  EXPECT_GT(share.pair_force, share.pair_contacts);  // the contacts beyond carry more than their number's share
  EXPECT_GT(share.wall_force, 0.5);                  // measured 0.955
  EXPECT_LT(summary.loaded_unbalanced_force_ratio, 1e-2);
  EXPECT_GE(summary.loaded_kinetic_over_elastic, 0.0);
  const std::vector<std::string> warnings = summary_warnings(summary);
  ASSERT_FALSE(warnings.empty());
  EXPECT_NE(warnings[0].find("of the force on the plates at the loaded state"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[0].find("c_c/r^ = 0.16"), std::string::npos) << warnings[0];
  RecordProperty("loaded_wall_force_beyond_fraction", std::to_string(share.wall_force));
  RecordProperty("loaded_pair_force_beyond_fraction", std::to_string(share.pair_force));

  // summary.txt: the existing keys first, then the energy balance and the loaded state.
  const std::string path = temporary("ellc_summary") + ".txt";
  write_summary_file(path, "calendering_quick.toml", summary);
  std::ifstream file(path);
  std::vector<std::string> keys;
  std::map<std::string, std::string> values;
  for (std::string line; std::getline(file, line);) {
    if (line.empty() || line[0] == '#') continue;
    const auto equals = line.find(" = ");
    ASSERT_NE(equals, std::string::npos) << line;
    keys.push_back(line.substr(0, equals));
    values[keys.back()] = line.substr(equals + 3);
  }
  std::remove(path.c_str());
  const std::vector<std::string> expected = {"finished",
                                             "particles",
                                             "steps",
                                             "time_us",
                                             "dt_us",
                                             "dt_estimate_us",
                                             "max_pressure_MPa",
                                             "loaded_thickness_um",
                                             "final_thickness_um",
                                             "springback_percent",
                                             "loaded_porosity",
                                             "final_porosity",
                                             "plastic_dissipation_pJ",
                                             "plastic_dissipation_calendering_pJ",
                                             "narrow_phase_failures",
                                             "plate_work_pJ",
                                             "plastic_share_of_plate_work",
                                             "gravity_work_pJ",
                                             "energy_residual_pJ",
                                             "energy_residual_fraction",
                                             "held_pressure_MPa",
                                             "loaded_time_us",
                                             "loaded_plate_speed_um_per_us",
                                             "released_time_us",
                                             "released_unbalanced_force_ratio",
                                             "released_pressure_MPa",
                                             "released_plate_speed_um_per_us",
                                             "loaded_inertial_number",
                                             "released_inertial_number",
                                             "loaded_state_recorded",
                                             "loaded_unbalanced_force_ratio",
                                             "loaded_kinetic_over_elastic",
                                             "validity_threshold",
                                             "validity_r_hat",
                                             "loaded_pair_contacts",
                                             "loaded_pair_contacts_beyond_fraction",
                                             "loaded_pair_force_beyond_fraction",
                                             "loaded_wall_contacts",
                                             "loaded_wall_contacts_beyond_fraction",
                                             "loaded_wall_force_beyond_fraction",
                                             "loaded_largest_size_ratio"};
  EXPECT_EQ(keys, expected);
  EXPECT_EQ(values["loaded_state_recorded"], "true");
  EXPECT_EQ(values["validity_threshold"], "0.16");
  EXPECT_EQ(values["validity_r_hat"], "\"smaller_particle_of_the_pair\"");
  EXPECT_EQ(values["loaded_pair_contacts"], std::to_string(v.pair_contacts));
  EXPECT_NEAR(std::stod(values["loaded_wall_force_beyond_fraction"]), share.wall_force, 1e-7);
}

// summary.txt is a TOML document, so any TOML reader takes it whole: every line a key of the
// right type, the words quoted. Also with the non-finite values of a run that ended early
// (a NaN springback, an infinite ratio), which C++ streams write as nan and inf, as TOML has them.
TEST(ScenarioValidity, SummaryIsATomlDocument) {
  RunSummary summary;
  summary.finished = false;
  summary.loaded_state_recorded = true;
  summary.springback_percent = std::numeric_limits<double>::quiet_NaN();
  summary.loaded_unbalanced_force_ratio = std::numeric_limits<double>::infinity();
  summary.particles_per_species = {60, 40};
  std::ostringstream text;
  write_summary_lines(text, "a.toml", summary);
  toml::table table;
  try {
    table = toml::parse(text.str());
  } catch (const toml::parse_error& error) {
    FAIL() << error.description() << " at line " << error.source().begin.line << " of\n" << text.str();
  }
  EXPECT_EQ(table["validity_r_hat"].value<std::string>(), "smaller_particle_of_the_pair");
  EXPECT_EQ(table["finished"].value<bool>(), false);
  EXPECT_TRUE(table["steps"].is_integer());
  EXPECT_TRUE(std::isnan(table["springback_percent"].value<double>().value_or(0.0)));
  EXPECT_TRUE(std::isinf(table["loaded_unbalanced_force_ratio"].value<double>().value_or(0.0)));
  EXPECT_EQ(table["species_1_particles"].value<std::int64_t>(), 40);
  std::size_t lines = 0;
  std::istringstream rows(text.str());
  for (std::string line; std::getline(rows, line);) lines += !line.empty() && line[0] != '#' ? 1U : 0U;
  EXPECT_EQ(table.size(), lines);  // nothing dropped or merged
}

// A summary with little force beyond the threshold gives no warning; more than half of the pair
// force beyond it gives one naming the pairs.
TEST(ScenarioValidity, WarningsOnlyWhenMoreThanHalfTheForceIsBeyond) {
  RunSummary summary;
  summary.loaded_state_recorded = true;
  summary.loaded_validity_shares = {0.9, 0.5, 0.9, 0.5};
  EXPECT_TRUE(summary_warnings(summary).empty());
  summary.loaded_validity_shares.pair_force = 0.6;
  const std::vector<std::string> warnings = summary_warnings(summary);
  ASSERT_EQ(warnings.size(), 1U);
  EXPECT_NE(warnings[0].find("60 % of the force between particles"), std::string::npos) << warnings[0];
  summary.loaded_state_recorded = false;
  EXPECT_TRUE(summary_warnings(summary).empty());
}

struct ContactFrame {
  std::size_t points = 0;
  std::size_t lines = 0;
  std::map<std::string, std::vector<double>> scalars;
  std::vector<double> force_z;
};

// Reads a contacts_<step>.vtk as the legacy VTK format lays it out.
ContactFrame read_contact_frame(const std::string& path) {
  std::ifstream in(path);
  ContactFrame frame;
  std::string word;
  std::string line;
  for (int k = 0; k < 4; ++k) std::getline(in, line);  // version, title, ASCII, DATASET POLYDATA
  EXPECT_EQ(line, "DATASET POLYDATA");
  in >> word >> frame.points >> line;
  EXPECT_EQ(word, "POINTS");
  for (std::size_t k = 0; k < 3 * frame.points; ++k) in >> word;
  std::size_t size = 0;
  in >> word >> frame.lines >> size;
  EXPECT_EQ(word, "LINES");
  EXPECT_EQ(size, 3 * frame.lines);
  for (std::size_t k = 0; k < frame.lines; ++k) {
    std::size_t count = 0, a = 0, b = 0;
    in >> count >> a >> b;
    EXPECT_EQ(count, 2U);
    EXPECT_EQ(a, 2 * k);
    EXPECT_EQ(b, 2 * k + 1);
  }
  if (!(in >> word)) return frame;
  EXPECT_EQ(word, "CELL_DATA");
  std::size_t cells = 0;
  in >> cells;
  EXPECT_EQ(cells, frame.lines);
  while (in >> word) {
    if (word == "SCALARS") {
      std::string name, type, components, lookup, table;
      in >> name >> type >> components >> lookup >> table;
      std::vector<double>& values = frame.scalars[name];
      values.resize(cells);
      for (double& value : values) in >> value;
    } else if (word == "VECTORS") {
      in >> word >> word;
      frame.force_z.resize(cells);
      for (double& z : frame.force_z) in >> word >> word >> z;
    }
  }
  return frame;
}

// vtk/contacts_<step>.vtk beside every particles frame: one line per contact, the cell data in
// step with the simulation (the plate's contacts sum to the plate force).
TEST(ScenarioOutputs, ContactFramesHaveOneLinePerContactWithItsCellData) {
  const std::string directory = temporary("ellc_contacts");
  RunOptions options;
  options.output_directory = directory;
  options.parallel_threshold = 512;
  const std::string text = replace_line(quick_scenario_text(), "vtk_every", "vtk_every = 1000");
  ScenarioRunner runner(quick_scenario(text), options);
  runner.advance(14000);  // into the calendering
  const auto& sim = runner.simulation();
  char name[64];
  std::snprintf(name, sizeof name, "/vtk/contacts_%09d.vtk", 14000);
  ASSERT_TRUE(std::filesystem::exists(directory + "/vtk/contacts_000000000.vtk"));
  ASSERT_TRUE(std::filesystem::exists(directory + "/vtk/particles_000014000.vtk"));
  const ContactFrame frame = read_contact_frame(directory + name);
  const engine::ContactCounts counts = sim.contact_counts();
  EXPECT_EQ(frame.lines, counts.particle_contacts + counts.wall_contacts);
  EXPECT_EQ(frame.points, 2 * frame.lines);
  ASSERT_GT(frame.lines, 50U);
  for (const char* field : {"normal_force", "overlap", "max_overlap", "regime", "size_ratio", "wall"})
    ASSERT_EQ(frame.scalars.count(field), 1U) << field;
  double plate = 0.0, largest = 0.0;
  for (std::size_t k = 0; k < frame.lines; ++k) {
    if (frame.scalars.at("wall")[k] == kTopWall) plate += frame.scalars.at("normal_force")[k];
    largest = std::max(largest, frame.scalars.at("size_ratio")[k]);
    EXPECT_GE(frame.scalars.at("max_overlap")[k], frame.scalars.at("overlap")[k] * (1 - 1e-8));
    EXPECT_LE(frame.scalars.at("regime")[k], 4.0);
  }
  EXPECT_NEAR(plate, sim.walls()[kTopWall].force.z(), 1e-6 * std::abs(plate) + 1e-9);
  EXPECT_NEAR(largest, sim.validity().largest_ratio, 1e-8);
  // The first frame, before any contact: points and lines, no cell data.
  const ContactFrame empty = read_contact_frame(directory + "/vtk/contacts_000000000.vtk");
  EXPECT_EQ(empty.lines, 0U);
  std::filesystem::remove_all(directory);
}

}  // namespace
}  // namespace ellc::scenario
