// [[species]] scenarios (docs/engine.md, "Several species"): the blend example reads, its packing
// has the species in their fractions (deterministic per seed), a short run and a restart keep
// them, and bad input is refused by name.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <unistd.h>

#include "ellc/scenario/packing.hpp"
#include "scenario_support.hpp"
#include "support/input_error.hpp"
#include "support/simulation_state.hpp"

namespace ellc::scenario {
namespace {

using test::input_error_message;
using testing::in_memory;
using testing::replace_line;

std::string blend_text() {
  std::ifstream in(std::string(ELLC_EXAMPLES_DIR) + "/calendering_blend.toml");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

Scenario blend(const std::string& text) { return parse_scenario(text, std::string(ELLC_EXAMPLES_DIR) + "/blend.toml"); }

// Replaces the n-th (0-based) line that starts with `starts_with`.
std::string replace_nth(std::string text, const std::string& starts_with, int n, const std::string& line) {
  std::size_t at = 0;
  for (int seen = -1;; ++at) {
    at = text.find("\n" + starts_with, at);
    if (at == std::string::npos) return text;
    if (++seen == n) break;
  }
  const std::size_t begin = at + 1;
  const std::size_t end = text.find('\n', begin);
  return text.replace(begin, end - begin, line);
}

TEST(ScenarioSpecies, BlendExampleReads) {
  const Scenario scenario = blend(blend_text());
  ASSERT_EQ(scenario.packing.species.size(), 2U);
  ASSERT_EQ(scenario.contact.species.size(), 2U);
  EXPECT_EQ(scenario.packing.species[0].name, "NMC");
  EXPECT_EQ(scenario.contact.species[1].youngs_modulus, 10000.0);
  EXPECT_TRUE(scenario.packing.species[1].spheres);
  EXPECT_EQ(scenario.packing.species[1].density, 1.8e-3 * scenario.mass_scaling);  // its own, scaled
  EXPECT_EQ(scenario.packing.species[0].density, 4.7e-3 * scenario.mass_scaling);  // [packing]'s
}

TEST(ScenarioSpecies, CountsFollowTheFractions) {
  std::vector<SpeciesSpec> species(3);
  species[0].fraction = 0.5;
  species[1].fraction = 0.3;
  species[2].fraction = 0.2;
  EXPECT_EQ(species_counts(species, 10), (std::vector<std::size_t>{5, 3, 2}));
  EXPECT_EQ(species_counts(species, 7), (std::vector<std::size_t>{4, 2, 1}));  // 3.5, 2.1, 1.4: remainder .5 first
  std::size_t total = 0;
  for (std::size_t n : species_counts(species, 1001)) total += n;
  EXPECT_EQ(total, 1001U);
}

TEST(ScenarioSpecies, PackingHasTheSpeciesDeterministicallyPerSeed) {
  const Scenario scenario = blend(blend_text());
  const engine::ParticleSet first = generate_packing(scenario.packing, scenario.box, 0.0);
  const engine::ParticleSet again = generate_packing(scenario.packing, scenario.box, 0.0);
  EXPECT_EQ(first.species, again.species);
  EXPECT_EQ(first.position, again.position);
  EXPECT_EQ(std::count(first.species.begin(), first.species.end(), 1), 8);  // 10 % of 80
  for (std::size_t k = 0; k < first.size(); ++k) {
    const SpeciesSpec& kind = scenario.packing.species[first.species[k]];
    const Eigen::Vector3d& axes = first.semi_axes[k];
    EXPECT_EQ(kind.spheres, axes.x() == axes.y() && axes.y() == axes.z()) << k;
    EXPECT_NEAR(first.mean_radius[k], kind.mean_radius, 2.0 * kind.radius_spread * kind.mean_radius + 1e-12) << k;
    EXPECT_NEAR(first.mass[k], kind.density * engine::ellipsoid_volume(axes), 1e-12 * first.mass[k]) << k;
  }
  PackingSpec other = scenario.packing;
  other.seed = 7;
  EXPECT_NE(generate_packing(other, scenario.box, 0.0).species, first.species);
}

// A 30-particle blend runs the whole protocol (about 10⁴ steps, half a second): at the end of the
// load pairs of both kinds touch, the summary counts the species, and a restart from the middle of
// the load reproduces the run bit for bit with its species.
TEST(ScenarioSpecies, BlendRunsAndRestartsWithItsSpecies) {
  const Scenario scenario = blend(replace_line(blend_text(), "count", "count = 30"));
  ScenarioRunner whole(scenario, in_memory(512));
  const auto loaded = [](const ScenarioRunner& runner) { return runner.state().phase == Phase::hold; };
  const std::uint64_t load_steps = whole.advance(1'000'000, loaded);
  std::size_t mixed = 0;
  std::size_t same = 0;
  const engine::Simulation& sim = whole.simulation();
  sim.for_each_contact([&](const engine::ContactView& view) {
    if (view.wall >= 0) return;
    ++(sim.particles().species[view.i] != sim.particles().species[view.j] ? mixed : same);
  });
  EXPECT_GT(mixed, 0U);
  EXPECT_GT(same, 0U);
  whole.advance(1'000'000);
  ASSERT_TRUE(whole.done());
  const RunSummary summary = whole.summary();
  EXPECT_TRUE(summary.finished);
  EXPECT_EQ(summary.particles_per_species, (std::vector<std::size_t>{27, 3}));
  std::ostringstream lines;
  write_summary_lines(lines, scenario.source, summary);
  EXPECT_NE(lines.str().find("species_0_particles = 27\nspecies_1_particles = 3\n"), std::string::npos) << lines.str();

  const std::string checkpoint =
      (std::filesystem::temp_directory_path() / ("ellc_species_" + std::to_string(::getpid()) + ".bin")).string();
  {
    ScenarioRunner first(scenario, in_memory(512));
    first.advance(load_steps / 2);
    first.write_checkpoint(checkpoint);
  }
  RunOptions options = in_memory(512);
  options.restart_path = checkpoint;
  ScenarioRunner second(scenario, options);
  second.advance(1'000'000);
  std::remove(checkpoint.c_str());
  EXPECT_EQ(second.simulation().particles().species, whole.simulation().particles().species);
  EXPECT_TRUE(ellc::test::state_bytes(second.simulation()) == ellc::test::state_bytes(whole.simulation()));
}

TEST(ScenarioSpeciesInput, FractionsThatDoNotSumToOneGiveTheSum) {
  const std::string text = replace_line(blend_text(), "fraction = 0.9", "fraction = 0.8");
  const std::string message = input_error_message([&] { (void)blend(text); });
  EXPECT_NE(message.find("species.fraction"), std::string::npos) << message;
  EXPECT_NE(message.find("0.9"), std::string::npos) << message;
  EXPECT_NE(message.find("sum to 1"), std::string::npos) << message;
}

TEST(ScenarioSpeciesInput, DisagreeingModelTablesNameTheKey) {
  std::string text = replace_nth(blend_text(), "[species.material]", 1,
                                 "[species.model]\nyield_pressure_factor = 1.5\n[species.material]");
  const std::string message = input_error_message([&] { (void)blend(text); });
  EXPECT_NE(message.find("species[1].model"), std::string::npos) << message;
  EXPECT_NE(message.find("yield_pressure_factor (1.6 vs 1.5)"), std::string::npos) << message;
  // The same table as the top-level one is accepted.
  text = replace_nth(blend_text(), "[species.material]", 1, "[species.model]\nhertz = \"hale\"\n[species.material]");
  EXPECT_NO_THROW((void)blend(text));
}

TEST(ScenarioSpeciesInput, BadSpeciesFieldsAreNamed) {
  const auto message = [](const std::string& text) { return input_error_message([&] { (void)blend(text); }); };
  EXPECT_NE(message(replace_line(blend_text(), "fraction = 0.1", "fraction = -0.1")).find("species[1].fraction = -0.1"),
            std::string::npos);
  EXPECT_NE(message(replace_nth(blend_text(), "mean_radius", 1, "mean_radius = 0.0")).find("species[1].mean_radius"),
            std::string::npos);
  EXPECT_NE(message(replace_nth(blend_text(), "youngs_modulus", 1, "youngs_modulus = -5.0"))
                .find("species[1].material.youngs_modulus"),
            std::string::npos);
  EXPECT_NE(message(replace_line(blend_text(), "count", "count = 60\nmean_radius = 4.0")).find("packing.mean_radius"),
            std::string::npos);
  EXPECT_NE(message("[material]\nyoungs_modulus = 1.0\npoisson_ratio = 0.2\nyield_stress = 1.0\n" + blend_text())
                .find("material = given"),
            std::string::npos);
  EXPECT_NE(message(replace_nth(blend_text(), "[species.material]", 1, "[species.materials]")).find("species[1]"),
            std::string::npos);
}

}  // namespace
}  // namespace ellc::scenario
