// SCENARIO.toml → Scenario. Uses the io layer's TableReader, so every key is checked and every
// error names its field (InputError → exit code 2 in the CLI).

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "ellc/cases/case_file.hpp"
#include "ellc/contact/contact_parameters.hpp"
#include "ellc/io/input_error.hpp"
#include "ellc/io/table_reader.hpp"
#include "ellc/io/toml_overrides.hpp"
#include "ellc/material/material.hpp"
#include "ellc/scenario/ensemble.hpp"
#include "ellc/scenario/packing_import.hpp"
#include "ellc/scenario/scenario.hpp"

namespace ellc::scenario {

using engine::ContactSettings;

namespace {

// The largest bounding radius of one size and shape distribution.
double largest_bounding_radius(double mean_radius, double radius_spread, double aspect_min, double aspect_max,
                               bool spheres) noexcept {
  const double radius = mean_radius * (1.0 + 2.0 * radius_spread);
  if (spheres) return radius;
  // Semi-axes r̂ (1, q1, q2) / (q1 q2)^{1/3}; the largest is reached at a corner of the range.
  double largest = 0.0;
  for (double q1 : {aspect_min, aspect_max})
    for (double q2 : {aspect_min, aspect_max})
      largest = std::max(largest, std::max({1.0, q1, q2}) / std::cbrt(q1 * q2));
  return radius * largest;
}

}  // namespace

double largest_bounding_radius(const PackingSpec& spec) noexcept {
  if (!spec.file.empty()) return spec.imported_bounding_radius;
  if (spec.species.empty())
    return largest_bounding_radius(spec.mean_radius, spec.radius_spread, spec.aspect_min, spec.aspect_max,
                                   spec.spheres);
  double largest = 0.0;
  for (const SpeciesSpec& s : spec.species)
    largest = std::max(largest,
                       largest_bounding_radius(s.mean_radius, s.radius_spread, s.aspect_min, s.aspect_max, s.spheres));
  return largest;
}

namespace {

constexpr double kMaxLength = 1e100;  // µm

double positive_or(TableReader& table, std::string_view key, double fallback) {
  if (!table.has(key)) return fallback;
  return table.positive(key);
}

double non_negative_or(TableReader& table, std::string_view key, double fallback) {
  if (!table.has(key)) return fallback;
  return table.non_negative(key);
}

// The shared contact-model vocabulary (src/ellc/contact/contact_parameters.hpp), plus the walls' μ
// under its older name (now [walls] friction).
void read_contact(TableReader& table, ContactSettings& contact) {
  ContactModelBuilder builder(contact.model);
  for (const ContactParameterName& parameter : kContactParameters) {
    if (!table.has(parameter.name)) continue;
    if (parameter.kind == ParameterKind::choice) {
      const std::string value = table.optional_string(parameter.name).value_or("");
      if (std::string expected = builder.set(parameter.name, value); !expected.empty())
        table.fail(parameter.name, "\"" + value + "\"", expected);
    } else {
      const double value = table.number(parameter.name);
      if (std::string expected = builder.set(parameter.name, value); !expected.empty())
        table.fail(parameter.name, value, expected);
    }
  }
  contact.model = builder.finish();
  contact.wall_friction = non_negative_or(table, "wall_friction", contact.wall_friction);
  if (contact.wall_friction > kMaxFriction)
    table.fail("wall_friction", contact.wall_friction, "a friction coefficient in [0, 10]");
  table.finish();
}

// [walls.material]: an elastic (or elastic–plastic) plate; without yield_stress it never yields.
Material read_wall_material(TableReader& table) {
  Material material;
  material.youngs_modulus = table.positive("youngs_modulus");
  material.poisson_ratio = table.number("poisson_ratio");
  if (!(material.poisson_ratio > -1.0 && material.poisson_ratio < 0.5))
    table.fail("poisson_ratio", material.poisson_ratio, "a Poisson ratio in the open interval (-1, 0.5)");
  material.yield_stress =
      table.has("yield_stress") ? table.positive("yield_stress") : std::numeric_limits<double>::infinity();
  table.finish();
  return material;
}

// [walls]: what the plates are made of, material = "particle" (default: the particles' own
// material, a mirror-image half-space), "rigid" or a [walls.material] table, and their μ.
// `material` is the raw node of walls.material, to tell its two forms apart.
void read_walls(TableReader& table, const toml::node* material, bool contact_gave_friction, ContactSettings& contact) {
  constexpr const char* kMaterialChoices =
      "one of \"particle\", \"rigid\", or a table [walls.material] with youngs_modulus, poisson_ratio and "
      "optionally yield_stress";
  if (material != nullptr && !material->is_table() && !material->is_string())
    table.fail("material", material->is_number() ? "a number" : "a value of another type", kMaterialChoices);
  if (material != nullptr && material->is_table()) {
    auto sub_table = table.table("material");
    contact.wall_material = read_wall_material(sub_table);
  } else if (const std::string name = table.optional_string("material").value_or("particle"); name == "rigid") {
    contact.wall_material = rigid_material();
  } else if (name == "particle") {
    contact.wall_material.reset();
  } else {
    table.fail("material", "\"" + name + "\"", kMaterialChoices);
  }
  if (table.has("friction")) {
    const double friction = table.non_negative("friction");
    if (friction > kMaxFriction) table.fail("friction", friction, "a friction coefficient in [0, 10]");
    if (contact_gave_friction)
      table.fail("friction", friction,
                 "one friction coefficient for the walls: [walls] friction or (the older name) [contact] "
                 "wall_friction, not both");
    contact.wall_friction = friction;
  }
  table.finish();
}

// The imported packing's count, mean r̂, largest semi-axis and shape (geometry only: unit densities;
// with several species, its atom types are checked against them).
void measure_imported_packing(Scenario& scenario) {
  PackingSpec& spec = scenario.packing;
  const std::size_t species = std::max<std::size_t>(1, spec.species.size());
  const engine::ParticleSet particles = import_packing(spec.file, std::vector<double>(species, 1.0), scenario.box);
  spec.count = particles.size();
  spec.mean_radius = 0.0;
  for (std::size_t k = 0; k < particles.size(); ++k) {
    spec.mean_radius += particles.mean_radius[k] / static_cast<double>(particles.size());
    spec.imported_bounding_radius = std::max(spec.imported_bounding_radius, particles.bounding_radius[k]);
  }
  spec.spheres = particles.all_spheres();
}

// [packing] file = "...": the particles of a file (packing_import.hpp), relative to the scenario;
// only density (and seed, unused) go with it. With [[species]], the file is measured once they are read.
void read_packing_file(TableReader& table, Scenario& scenario, bool several_species) {
  PackingSpec& spec = scenario.packing;
  const std::filesystem::path given = table.optional_string("file").value_or("");
  spec.file = (given.is_absolute() ? given : std::filesystem::path(scenario.path).parent_path() / given).string();
  scenario.material_density = table.positive("density");
  spec.seed = static_cast<std::uint64_t>(table.integer_at_least("seed", 0, 1));
  table.finish();
  if (!several_species) measure_imported_packing(scenario);
}

// The size and shape distribution of one population of particles: [packing] of a one-species
// scenario, or one [[species]] table (PackingSpec and SpeciesSpec name these fields alike).
template <typename Population>
void read_size_and_shape(TableReader& table, Population& spec, std::vector<std::string>& warnings) {
  spec.mean_radius = table.positive("mean_radius");
  if (spec.mean_radius > kMaxLength) table.fail("mean_radius", spec.mean_radius, "a radius in (0, 1e100] µm");
  spec.radius_spread = non_negative_or(table, "radius_spread", 0.0);
  if (spec.radius_spread >= 0.45) table.fail("radius_spread", spec.radius_spread, "a relative spread in [0, 0.45)");
  spec.spheres = table.choice("shape", {"ellipsoid", "sphere"}, "ellipsoid") == "sphere";
  if (const auto aspect = table.optional_numbers("aspect", 2)) {
    if ((*aspect)[0] <= 0.0 || (*aspect)[1] < (*aspect)[0])
      table.fail("aspect", "[" + format_number((*aspect)[0]) + ", " + format_number((*aspect)[1]) + "]",
                 "[min, max] with 0 < min <= max (ratios b/a and c/a)");
    spec.aspect_min = (*aspect)[0];
    spec.aspect_max = (*aspect)[1];
  }
  if (!spec.spheres && (spec.aspect_min < 0.5 * (1 - 1e-12) || spec.aspect_max > 2.0 * (1 + 1e-12)))
    warnings.push_back(table.field("aspect") +
                       " extends outside the calibrated range 1:[0.5..2]:[0.5..2] of the "
                       "transition fits (eq. 52-53); the law still evaluates");
}

void read_particle_count(TableReader& table, PackingSpec& spec) {
  spec.count = static_cast<std::size_t>(table.integer_at_least("count", 1));
  if (spec.count > 50'000'000) table.fail("count", std::to_string(spec.count), "at most 50000000 particles");
}

// [packing]'s seed(s), density and insertion fraction, with one species or several; then no other key.
void read_seeds_density_and_insertion(TableReader& table, Scenario& scenario) {
  PackingSpec& spec = scenario.packing;
  spec.seed = static_cast<std::uint64_t>(table.integer_at_least("seed", 0, 1));
  scenario.seeds = read_packing_seeds(table);  // an ensemble over packing seeds (ensemble.hpp)
  scenario.material_density = table.positive("density");
  spec.insertion_fraction = positive_or(table, "insertion_fraction", spec.insertion_fraction);
  if (spec.insertion_fraction > 0.5)
    table.fail("insertion_fraction", spec.insertion_fraction, "a solid fraction in (0, 0.5]");
  table.finish();
}

void read_packing(TableReader& table, Scenario& scenario) {
  if (table.has("file")) {
    read_packing_file(table, scenario, false);
    return;
  }
  read_particle_count(table, scenario.packing);
  read_size_and_shape(table, scenario.packing, scenario.warnings);
  read_seeds_density_and_insertion(table, scenario);
}

// [packing] of a scenario with [[species]]: the blend's count, seed(s), density and insertion; the
// size and shape distributions are the species'.
void read_blend_packing(TableReader& table, Scenario& scenario) {
  for (const char* key : {"mean_radius", "radius_spread", "shape", "aspect"})
    if (table.has(key))
      table.fail(key, "given", std::string("[[species]] ") + key + ": with several species, each gives its own");
  if (table.has("file")) {  // a LAMMPS data file whose atom types are the species
    read_packing_file(table, scenario, true);
    return;
  }
  read_particle_count(table, scenario.packing);
  read_seeds_density_and_insertion(table, scenario);
}

// One [[species]] table: name, fraction, its size and shape distribution (the keys of [packing] in
// a one-species scenario), optional density, [species.material] and optional [species.model].
SpeciesSpec read_species(TableReader& table, Scenario& scenario, Material& material, ModelSpec& model) {
  SpeciesSpec species;
  species.name = table.optional_string("name").value_or("");
  species.fraction = table.number("fraction");
  if (!(species.fraction > 0.0 && species.fraction <= 1.0))
    table.fail("fraction", species.fraction, "a number fraction in (0, 1]");
  read_size_and_shape(table, species, scenario.warnings);
  species.density = positive_or(table, "density", scenario.material_density);
  {
    auto material_table = table.table("material");
    material = read_material(material_table);
  }
  if (auto model_table = table.optional_table("model")) model = read_model(*model_table);
  table.finish();
  return species;
}

// A sum for messages: 6 significant digits (0.6 + 0.3 is 0.9, not 0.8999999999999999).
std::string short_number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

// Fractions that sum to 1 within this (a blend written with rounded fractions, e.g. 1/3 as 0.333333).
constexpr double kFractionTolerance = 1e-6;

// [[species]]: the species' distributions into the packing, their materials into the contact
// settings; every species' [model] (or the top-level one) must be the same, since any two species
// may touch and a contact has one law.
void read_all_species(std::vector<TableReader>& tables, Scenario& scenario, const ModelSpec& top_model) {
  std::vector<ModelSpec> models;
  std::vector<std::string> model_where;
  double sum = 0.0;
  std::string fractions;
  for (TableReader& table : tables) {
    Material material;
    ModelSpec model = top_model;
    const bool own_model = table.has("model");
    SpeciesSpec species = read_species(table, scenario, material, model);
    if (species.name.empty()) species.name = "species" + std::to_string(scenario.packing.species.size());
    sum += species.fraction;
    fractions += (fractions.empty() ? "" : " + ") + format_number(species.fraction);
    scenario.packing.species.push_back(species);
    scenario.contact.species.push_back(material);
    models.push_back(model);
    model_where.push_back(own_model ? table.path() + ".model" : table.path() + " (the top-level [model])");
  }
  if (scenario.packing.species.size() > 65535)
    throw InputError(scenario.source, "species", std::to_string(scenario.packing.species.size()) + " species",
                     "at most 65535 species");
  if (!(std::abs(sum - 1.0) <= kFractionTolerance))
    throw InputError(scenario.source, "species.fraction", "a sum of " + short_number(sum) + " (" + fractions + ")",
                     "number fractions of the [[species]] that sum to 1 (within 1e-6)");
  for (std::size_t k = 1; k < models.size(); ++k) {
    const std::vector<ModelDifference> differences = model_differences(models[0], models[k]);
    if (differences.empty()) continue;
    std::string keys;
    for (const ModelDifference& d : differences)
      keys += (keys.empty() ? "" : ", ") + d.key + " (" + d.first + " vs " + d.second + ")";
    throw InputError(scenario.source,
                     model_where[k] + " differs from " + model_where[0] + " in " + keys +
                         ": expected one [model] for every species, since any two species may touch and a contact "
                         "has one law; give these keys the same values in every [species.model], or give one "
                         "top-level [model] (form = \"stiffness_ratio\" lets the law follow each pair's E_e/Y)");
  }
  scenario.contact.material = scenario.contact.species.front();
  scenario.contact.model.hertz = models.front().hertz;
  scenario.contact.model.law = models.front().law;
  PackingSpec& spec = scenario.packing;
  if (!spec.file.empty()) {  // the file's particles, its atom types the species
    measure_imported_packing(scenario);
    return;
  }
  // The blend as one distribution, for estimates (layer height, solid thickness): the radius of the
  // mean particle volume; spheres if every species is.
  double mean_cube = 0.0;
  spec.spheres = true;
  for (const SpeciesSpec& species : spec.species) {
    mean_cube += species.fraction / sum * std::pow(species.mean_radius, 3);
    spec.spheres = spec.spheres && species.spheres;
  }
  spec.mean_radius = std::cbrt(mean_cube);
}

void read_box(TableReader& table, Scenario& scenario) {
  const auto size = table.numbers("size", 2);
  // Lengths up to 1e100 µm keep squared distances, areas and volumes finite (docs/input_limits.md).
  for (int axis = 0; axis < 2; ++axis)
    if (!(size[axis] > 0.0 && size[axis] <= kMaxLength))
      table.fail("size[" + std::to_string(axis) + "]", size[axis], "a box length in (0, 1e100] µm");
  scenario.box = {size[0], size[1]};
  table.finish();
}

void read_time(TableReader& table, Scenario& scenario) {
  if (table.has("dt")) scenario.dt = table.positive("dt");
  scenario.time_step_safety = positive_or(table, "safety", scenario.time_step_safety);
  if (scenario.time_step_safety > 1.0) table.fail("safety", scenario.time_step_safety, "a factor in (0, 1]");
  scenario.mass_scaling = positive_or(table, "mass_scaling", 1.0);
  if (scenario.mass_scaling < 1.0) table.fail("mass_scaling", scenario.mass_scaling, "a density factor >= 1");
  scenario.skin = non_negative_or(table, "skin", 0.0);
  scenario.max_speed = positive_or(table, "max_speed", scenario.max_speed);
  table.finish();
}

void read_settle(TableReader& table, SettleSpec& settle) {
  settle.gravity = non_negative_or(table, "gravity", settle.gravity);
  settle.drag_rate = non_negative_or(table, "drag_rate", settle.drag_rate);
  settle.time = non_negative_or(table, "time", settle.time);
  settle.max_time = non_negative_or(table, "max_time", 0.0);
  if (settle.max_time == 0.0) settle.max_time = 3.0 * settle.time;  // 0 or absent: the default (scenario.hpp)
  if (settle.max_time < settle.time)
    table.fail("max_time", settle.max_time, "a time >= settle.time (µs), or 0 for 3 x settle.time");
  settle.speed_tolerance = positive_or(table, "speed_tolerance", settle.speed_tolerance);
  table.finish();
}

void read_calendering(TableReader& table, CalenderingSpec& spec) {
  spec.speed = table.positive("speed");
  spec.lift_speed = positive_or(table, "lift_speed", spec.speed);
  spec.approach_speed = non_negative_or(table, "approach_speed", 0.0);
  spec.approach_pressure = positive_or(table, "approach_pressure", spec.approach_pressure);
  if (table.has("target_thickness")) spec.target_thickness = table.number("target_thickness");
  if (table.has("target_pressure")) spec.target_pressure = table.positive("target_pressure");
  if (!spec.target_thickness && !spec.target_pressure)
    table.fail("target_thickness", "missing", "target_thickness (µm) or target_pressure (MPa), or both");
  if (spec.target_thickness && *spec.target_thickness <= 0.0)
    table.fail("target_thickness", *spec.target_thickness, "a plate gap > 0 µm (the walls would overlap)");
  spec.hold_time = non_negative_or(table, "hold_time", spec.hold_time);
  spec.gravity = non_negative_or(table, "gravity", spec.gravity);
  spec.start_gap = non_negative_or(table, "start_gap", spec.start_gap);
  if (spec.start_gap > kMaxLength) table.fail("start_gap", spec.start_gap, "a gap in [0, 1e100] µm");
  if (spec.target_thickness && *spec.target_thickness > kMaxLength)
    table.fail("target_thickness", *spec.target_thickness, "a plate gap in (0, 1e100] µm");
  spec.release_fraction = non_negative_or(table, "release_fraction", spec.release_fraction);
  if (spec.release_fraction >= 1.0) table.fail("release_fraction", spec.release_fraction, "a fraction in [0, 1)");
  spec.ramp_time = non_negative_or(table, "ramp_time", spec.ramp_time);
  spec.approach_window = non_negative_or(table, "approach_window", spec.approach_window);
  if (table.has("approach_solid_fraction")) {
    spec.approach_solid_fraction = table.positive("approach_solid_fraction");
    if (*spec.approach_solid_fraction >= 1.0)
      table.fail("approach_solid_fraction", *spec.approach_solid_fraction, "a solid fraction in (0, 1)");
  }
  spec.servo_hold = table.choice("hold", {"fixed", "servo"}, "fixed") == "servo";
  spec.servo_gain = positive_or(table, "servo_gain", spec.servo_gain);
  spec.servo_tolerance = non_negative_or(table, "servo_tolerance", spec.servo_tolerance);
  if (spec.servo_tolerance >= 0.5)
    table.fail("servo_tolerance", spec.servo_tolerance, "a relative pressure error in [0, 0.5)");
  spec.equilibrium_ratio = positive_or(table, "equilibrium_ratio", spec.equilibrium_ratio);
  spec.max_hold_time = non_negative_or(table, "max_hold_time", spec.max_hold_time);
  if (spec.max_hold_time > 0.0 && spec.max_hold_time < spec.hold_time)
    table.fail("max_hold_time", spec.max_hold_time, "a time >= hold_time = " + format_number(spec.hold_time) + " µs");
  spec.relax_time = non_negative_or(table, "relax_time", spec.relax_time);
  spec.rest_drag_rate = non_negative_or(table, "rest_drag_rate", spec.rest_drag_rate);
  spec.max_relax_time = non_negative_or(table, "max_relax_time", spec.max_relax_time);
  if (spec.max_relax_time > 0.0 && spec.max_relax_time < spec.relax_time)
    table.fail("max_relax_time", spec.max_relax_time,
               "a time >= relax_time = " + format_number(spec.relax_time) + " µs");
  spec.servo_release = table.choice("release", {"contact_lost", "servo"}, "contact_lost") == "servo";
  spec.release_pressure_fraction = positive_or(table, "release_pressure_fraction", spec.release_pressure_fraction);
  if (spec.release_pressure_fraction >= 0.5)
    table.fail("release_pressure_fraction", spec.release_pressure_fraction,
               "a fraction in (0, 0.5) of the held pressure: the residual pressure the released state is read at");
  spec.release_tolerance = positive_or(table, "release_tolerance", spec.release_tolerance);
  if (spec.release_tolerance >= 0.5)
    table.fail("release_tolerance", spec.release_tolerance, "a relative pressure error in (0, 0.5)");
  table.finish();
}

void read_output(TableReader& table, OutputSpec& output) {
  if (const auto directory = table.optional_string("directory")) output.directory = *directory;
  output.csv_every = table.integer_at_least("csv_every", 1, output.csv_every);
  output.vtk_every = table.integer_at_least("vtk_every", 0, output.vtk_every);
  output.checkpoint_every = table.integer_at_least("checkpoint_every", 0, output.checkpoint_every);
  table.finish();
}

AnalysisSpec read_analysis(TableReader& table) {
  AnalysisSpec spec;
  spec.voxels_per_semi_axis = positive_or(table, "voxels_per_semi_axis", spec.voxels_per_semi_axis);
  spec.spacing = positive_or(table, "spacing", 0.0);
  spec.memory_limit_gib = positive_or(table, "memory_limit_gib", spec.memory_limit_gib);
  spec.coarse_factor = table.number_or("coarse_factor", spec.coarse_factor);
  if (!(spec.coarse_factor >= 1.0))
    table.fail("coarse_factor", spec.coarse_factor, "a factor >= 1 (1: no second resolution)");
  if (const auto axes = table.optional_string("axes")) {
    if (axes->empty() || axes->find_first_not_of("xyz") != std::string::npos)
      table.fail("axes", "\"" + *axes + "\"", "the tortuosity directions, some of x, y, z (e.g. \"z\" or \"xyz\")");
    spec.axes = *axes;
  }
  table.finish();
  return spec;
}

// Checks that need several tables at once.
void cross_check(const Scenario& scenario) {
  const PackingSpec& spec = scenario.packing;
  const double largest = largest_bounding_radius(spec);
  const double skin = scenario.skin > 0.0 ? scenario.skin : 0.1 * largest;
  const double needed = 2.0 * (2.0 * largest + skin);
  const double shortest = std::min(scenario.box.lx, scenario.box.ly);
  if (shortest < needed)
    throw InputError(scenario.source, "box.size", format_number(shortest),
                     "box lengths >= " + format_number(needed) +
                         " µm: twice the reach 2 R_max + skin of the largest particle (packing.mean_radius = " +
                         format_number(spec.mean_radius) + " µm, bounding radius up to " + format_number(largest) +
                         " µm); the particle is too large for the periodic box");
  // The plate pushes particles at its own speed: faster than the runaway limit it would stop the
  // run (or, far faster, pass through the layer within a step).
  const CalenderingSpec& calendering = scenario.calendering;
  for (const auto& [key, speed] :
       {std::pair{"speed", calendering.speed}, std::pair{"approach_speed", calendering.approach_speed},
        std::pair{"lift_speed", calendering.lift_speed}})
    if (speed > scenario.max_speed)
      throw InputError(scenario.source, std::string("calendering.") + key, format_number(speed),
                       "a plate speed <= time.max_speed = " + format_number(scenario.max_speed) +
                           " µm/µs (the runaway limit: the particles the plate pushes would exceed it)");
  const double particle_volume = 4.0 / 3.0 * 3.141592653589793 * std::pow(largest, 3);
  if (!std::isfinite(particle_volume * static_cast<double>(spec.count)))
    throw InputError(scenario.source, "packing.mean_radius", format_number(spec.mean_radius),
                     "a radius whose particles' total volume stays finite (docs/input_limits.md)");
  if (const auto& target = scenario.calendering.target_thickness) {
    const double solid = static_cast<double>(spec.count) * 4.0 / 3.0 * 3.141592653589793 *
                         std::pow(spec.mean_radius, 3) / (scenario.box.lx * scenario.box.ly);
    if (*target <= solid)
      throw InputError(scenario.source, "calendering.target_thickness", format_number(*target),
                       "a plate gap > " + format_number(solid) +
                           " µm, the thickness of the solid alone (the walls would overlap the particles)");
  }
  if (scenario.calendering.servo_hold && !scenario.calendering.target_pressure)
    throw InputError(scenario.source, "calendering.hold", "\"servo\"",
                     "\"fixed\", or a target_pressure for the servo to hold");
}

Scenario read(const toml::table& root_table, const std::string& path, const std::string& source, std::string text) {
  TableReader root(root_table, "", source);
  Scenario scenario;
  scenario.source = source;
  scenario.path = path;
  scenario.text = std::move(text);
  std::vector<TableReader> species_tables = root.tables("species");
  const bool several_species = !species_tables.empty();
  if (several_species) {
    if (root.has("material"))
      root.fail("material", "given",
                "no top-level [material] with [[species]]: each species gives its own [species.material]");
  } else {
    auto material = root.table("material");
    scenario.contact.material = read_material(material);
  }
  ModelSpec top_model;
  if (auto model = root.optional_table("model")) {
    top_model = read_model(*model);
    scenario.contact.model.hertz = top_model.hertz;
    scenario.contact.model.law = top_model.law;
  }
  bool contact_gave_wall_friction = false;
  if (auto contact = root.optional_table("contact")) {
    contact_gave_wall_friction = contact->has("wall_friction");
    read_contact(*contact, scenario.contact);
  }
  if (auto walls = root.optional_table("walls"))
    read_walls(*walls, root_table["walls"]["material"].node(), contact_gave_wall_friction, scenario.contact);
  {
    auto box = root.table("box");
    read_box(box, scenario);
  }
  {
    auto packing = root.table("packing");
    if (several_species)
      read_blend_packing(packing, scenario);
    else
      read_packing(packing, scenario);
  }
  if (several_species) read_all_species(species_tables, scenario, top_model);
  if (auto time = root.optional_table("time")) read_time(*time, scenario);
  if (auto settle = root.optional_table("settle")) read_settle(*settle, scenario.settle);
  {
    auto calendering = root.table("calendering");
    read_calendering(calendering, scenario.calendering);
  }
  if (auto output = root.optional_table("output")) read_output(*output, scenario.output);
  if (auto analysis = root.optional_table("analysis")) scenario.analysis = read_analysis(*analysis);
  root.finish();
  scenario.packing.density = scenario.material_density * scenario.mass_scaling;
  for (SpeciesSpec& species : scenario.packing.species) species.density *= scenario.mass_scaling;
  cross_check(scenario);
  return scenario;
}

}  // namespace

Scenario read_scenario(const std::string& path, const std::vector<std::string>& overrides) {
  return parse_scenario(read_text_file(path), path, overrides);
}

Scenario parse_scenario(std::string_view toml_text, const std::string& source,
                        const std::vector<std::string>& overrides) {
  if (overrides.empty()) return read(parse_toml_text(toml_text, source), source, source, std::string(toml_text));
  toml::table root = parse_toml_text(toml_text, source);
  apply_toml_overrides(root, overrides);
  // The overrides are part of the input: in every message, the summary's header, and the text whose
  // hash a checkpoint carries (so --restart needs the same --set entries).
  std::string text(toml_text);
  for (const std::string& entry : overrides) text += "\n# --set " + entry;
  return read(root, source, describe_overrides(source, overrides), std::move(text));
}

}  // namespace ellc::scenario
