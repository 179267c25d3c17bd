// The [walls] table: what the plates are made of and their friction, the errors of bad input,
// and what a rigid plate changes (the stiffer wall contacts carry more pressure at the same gap).
// The physics check poses one sphere between the plates rather than calendering a packing: two
// packings pressed to the same gap with different walls follow different (chaotic) paths, and
// the quick example's plate pressure at 25.5 µm came out lower with rigid plates (88 MPa
// against 116 MPa) although every wall contact is stiffer.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "ellc/engine/simulation.hpp"
#include "scenario_support.hpp"
#include "support/input_error.hpp"

namespace ellc::scenario {
namespace {

using engine::kBottomWall;
using engine::kTopWall;
using engine::ParticleSet;
using engine::Simulation;
using engine::Wall;
using test::input_error_message;
using testing::in_memory;
using testing::quick_scenario;
using testing::quick_scenario_text;
using testing::replace_line;

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The quick example with `walls` in place of its [walls] table (up to the next blank line).
std::string with_walls(const std::string& walls) {
  std::string text = quick_scenario_text();
  const auto start = text.find("\n[walls]");
  const auto end = text.find("\n\n", start + 1);
  if (start == std::string::npos || end == std::string::npos) throw std::runtime_error("no [walls] table");
  return text.replace(start + 1, end - start - 1, walls);
}

TEST(ScenarioWalls, MaterialAndFrictionAreReadInEveryForm) {
  const Scenario example = quick_scenario(quick_scenario_text());
  EXPECT_FALSE(example.contact.wall_material.has_value());  // "particle": the particles' own material
  EXPECT_EQ(example.contact.wall_friction, 0.3);
  // No [walls] table: the same, and [contact] wall_friction, the older name, is still read.
  const auto older = quick_scenario(replace_line(with_walls(""), "friction", "friction = 0.3\nwall_friction = 0.4"));
  EXPECT_FALSE(older.contact.wall_material.has_value());
  EXPECT_EQ(older.contact.wall_friction, 0.4);
  EXPECT_EQ(older.contact.model.friction, 0.3);

  EXPECT_FALSE(quick_scenario(with_walls("[walls]\nmaterial = \"particle\"")).contact.wall_material.has_value());
  const auto rigid = quick_scenario(with_walls("[walls]\nmaterial = \"rigid\"\nfriction = 0.5")).contact;
  ASSERT_TRUE(rigid.wall_material.has_value());
  EXPECT_EQ(rigid.wall_material->youngs_modulus, kInfinity);
  EXPECT_EQ(rigid.wall_material->yield_stress, kInfinity);
  EXPECT_EQ(rigid.wall_friction, 0.5);
  // The runner hands them to the engine.
  const ScenarioRunner runner(quick_scenario(with_walls("[walls]\nmaterial = \"rigid\"\nfriction = 0.5")),
                              in_memory());
  EXPECT_EQ(runner.simulation().settings().contact.wall_material->youngs_modulus, kInfinity);
  EXPECT_EQ(runner.simulation().settings().contact.wall_friction, 0.5);

  const auto steel =
      quick_scenario(with_walls("[walls]\nfriction = 0.2\n[walls.material]\nyoungs_modulus = 210000.0\n"
                                "poisson_ratio = 0.3"))
          .contact;
  ASSERT_TRUE(steel.wall_material.has_value());
  EXPECT_EQ(steel.wall_material->youngs_modulus, 210000.0);
  EXPECT_EQ(steel.wall_material->poisson_ratio, 0.3);
  EXPECT_EQ(steel.wall_material->yield_stress, kInfinity);  // no yield_stress: never yields
  EXPECT_EQ(steel.wall_friction, 0.2);
  const auto soft = quick_scenario(with_walls("[walls.material]\nyoungs_modulus = 70000\npoisson_ratio = -0.2\n"
                                              "yield_stress = 300"))
                        .contact;
  EXPECT_EQ(soft.wall_material->yield_stress, 300.0);
  EXPECT_EQ(soft.wall_material->poisson_ratio, -0.2);
  EXPECT_EQ(soft.wall_friction, 0.3);  // the default
}

TEST(ScenarioWalls, BadInputNamesFieldValueAndExpectation) {
  const auto message = [](const std::string& walls) {
    return input_error_message([&] { (void)quick_scenario(with_walls(walls)); });
  };
  const std::string material = "[walls.material]\nyoungs_modulus = 210000.0\n";
  for (const char* nu : {"0.5", "-1", "0.7"}) {
    const std::string text = message(material + "poisson_ratio = " + nu);
    EXPECT_NE(text.find(std::string("walls.material.poisson_ratio = ") + nu + ": expected"), std::string::npos) << text;
    EXPECT_NE(text.find("(-1, 0.5)"), std::string::npos) << text;
  }
  const std::string modulus = message("[walls.material]\nyoungs_modulus = 0\npoisson_ratio = 0.3");
  EXPECT_NE(modulus.find("walls.material.youngs_modulus = 0: expected a finite number > 0"), std::string::npos)
      << modulus;
  const std::string yield = message(material + "poisson_ratio = 0.3\nyield_stress = -5");
  EXPECT_NE(yield.find("walls.material.yield_stress = -5: expected a finite number > 0"), std::string::npos) << yield;
  const std::string missing = message("[walls.material]\nyoungs_modulus = 210000.0");
  EXPECT_NE(missing.find("walls.material.poisson_ratio = missing"), std::string::npos) << missing;
  const std::string name = message("[walls]\nmaterial = \"steel\"");
  EXPECT_NE(name.find("walls.material = \"steel\": expected one of \"particle\", \"rigid\", or a table"),
            std::string::npos)
      << name;
  const std::string number = message("[walls]\nmaterial = 3");
  EXPECT_NE(number.find("walls.material = a number: expected one of"), std::string::npos) << number;
  EXPECT_NE(message("[walls]\ncolour = \"grey\"").find("walls.colour"), std::string::npos);
  EXPECT_NE(message(material + "poisson_ratio = 0.3\ndensity = 7.8e-3").find("walls.material.density"),
            std::string::npos);
  EXPECT_NE(message("[walls]\nfriction = -0.1").find("walls.friction = -0.1: expected a finite number >= 0"),
            std::string::npos);
  // The friction of the walls once: [walls] friction or [contact] wall_friction, not both.
  const std::string both = input_error_message([&] {
    (void)quick_scenario(replace_line(quick_scenario_text(), "friction", "friction = 0.3\nwall_friction = 0.3"));
  });
  EXPECT_NE(both.find("walls.friction = 0.3: expected one friction coefficient"), std::string::npos) << both;
  EXPECT_NE(both.find("[contact] wall_friction"), std::string::npos) << both;
}

// One NMC sphere (r = 4 µm) pressed between floor and plate to the same gap, 2 r − 2 δ: each
// wall contact is the Hertz contact of the sphere and a flat (elastic at δ = 0.02 µm, far below
// δ_Y), F = 4/3 E_e √r δ^{3/2}, so the plate pressure scales with E_e of eq. (3): a rigid plate
// doubles it against one of the particles' own material, a steel plate sits in between.
TEST(ScenarioWalls, RigidPlateRaisesThePlatePressureAtTheSameGap) {
  const double radius = 4.0;
  const double overlap = 0.02;
  const auto plate_pressure = [&](const std::string& walls) {
    const Scenario scenario = quick_scenario(walls.empty() ? quick_scenario_text() : with_walls(walls));
    engine::EngineSettings settings;
    settings.contact = scenario.contact;
    settings.box = scenario.box;
    ParticleSet particles;
    particles.add(0, Eigen::Vector3d::Constant(radius), scenario.packing.density, {20.0, 20.0, radius - overlap},
                  Eigen::Quaterniond::Identity());
    const Simulation sim(settings, particles,
                         {Wall{0.0, 0.0, 1, {}}, Wall{2.0 * (radius - overlap), 0.0, -1, {}}});
    EXPECT_EQ(sim.contact_counts().wall_contacts, 2U);
    return sim.wall_pressure(kTopWall);
  };
  const double particle = plate_pressure("");
  const double rigid = plate_pressure("[walls]\nmaterial = \"rigid\"");
  const double steel = plate_pressure("[walls.material]\nyoungs_modulus = 210000.0\npoisson_ratio = 0.3");
  RecordProperty("plate_pressure_particle_MPa", std::to_string(particle));
  RecordProperty("plate_pressure_rigid_MPa", std::to_string(rigid));
  const Material nmc = quick_scenario(quick_scenario_text()).contact.material;
  const double particle_modulus = effective_modulus(nmc, nmc);
  EXPECT_GT(particle, 0.0);
  EXPECT_NEAR(rigid / particle, effective_modulus(nmc, rigid_material()) / particle_modulus, 1e-9);
  EXPECT_NEAR(rigid / particle, 2.0, 1e-9);
  EXPECT_NEAR(steel / particle, effective_modulus(nmc, Material{210000.0, 0.3, kInfinity}) / particle_modulus, 1e-9);
  EXPECT_GT(steel, particle);
  EXPECT_LT(steel, rigid);
  // Hertz itself: F = 4/3 E_e √r δ^{3/2} over the box.
  const double box = 42.0 * 42.0;
  EXPECT_NEAR(rigid * box, 4.0 / 3.0 * effective_modulus(nmc, rigid_material()) * std::sqrt(radius) *
                               std::pow(overlap, 1.5),
              1e-6 * rigid * box);
}

}  // namespace
}  // namespace ellc::scenario
