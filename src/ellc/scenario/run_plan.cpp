#include "ellc/scenario/run_plan.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include "ellc/engine/time_step.hpp"
#include "ellc/io/input_error.hpp"

namespace ellc::scenario {

namespace {

// Rough sizes, generous rather than tight (measured on the examples, docs/input_limits.md).
constexpr double kBytesPerParticle = 2000.0;    // the particle arrays, body frames, wall histories
constexpr double kPairsPerParticle = 16.0;      // candidate pairs with the skin, dense packing
constexpr double kBytesPerPair = 700.0;         // slot, spare slot, result, budget, index
constexpr double kBytesPerGridCell = 8.0;       // the dense cell grid's offsets
constexpr double kCsvBytesPerRow = 600.0;       // ~40 columns
constexpr double kVtkBytesPerParticle = 700.0;  // ASCII: position, id, radius, velocity, force, shape
constexpr double kCheckpointBytesPerParticle = 3000.0;
constexpr double kImpossibleSteps = 1e13;  // months even at a million steps per second

// The smallest semi-axis the spec can draw: r̂ (1 − 2σ) times the smallest axis ratio factor.
double smallest_semi_axis(const SpeciesSpec& spec) noexcept {
  const double radius = spec.mean_radius * (1.0 - 2.0 * spec.radius_spread);
  if (spec.spheres) return radius;
  double smallest = 1.0;
  for (double q1 : {spec.aspect_min, spec.aspect_max})
    for (double q2 : {spec.aspect_min, spec.aspect_max})
      smallest = std::min(smallest, std::min({1.0, q1, q2}) / std::cbrt(q1 * q2));
  return radius * smallest;
}

// An estimate in messages: three significant digits (format_number is for what the user wrote).
std::string approx(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

struct Phase {
  const char* name;
  const char* fields;
  double time;
};

}  // namespace

std::string format_bytes(double bytes) {
  static constexpr const char* kUnits[] = {"B", "kB", "MB", "GB", "TB", "PB", "EB"};
  if (!std::isfinite(bytes)) return approx(bytes) + " B";
  int unit = 0;
  while (bytes >= 1000.0 && unit < 6) {
    bytes /= 1000.0;
    ++unit;
  }
  if (bytes >= 1000.0) return approx(bytes * 1e18) + " B";
  char text[32];
  std::snprintf(text, sizeof text, "%.3g %s", bytes, kUnits[unit]);
  return text;
}

RunPlan plan_run(const Scenario& scenario) {
  RunPlan plan;
  const PackingSpec& spec = scenario.packing;
  const CalenderingSpec& calendering = scenario.calendering;
  const double count = static_cast<double>(spec.count);
  // The shortest Rayleigh time over the species, each at its smallest semi-axis.
  const std::vector<SpeciesSpec> species = species_of(spec);
  const std::vector<Material> materials = engine::species_materials(scenario.contact);
  plan.smallest_semi_axis = std::numeric_limits<double>::infinity();
  double rayleigh = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < species.size(); ++k) {
    const double axis = smallest_semi_axis(species[k]);
    plan.smallest_semi_axis = std::min(plan.smallest_semi_axis, axis);
    rayleigh = std::min(rayleigh, engine::rayleigh_time(axis, species[k].density, materials[k]));
  }
  plan.time_step = scenario.dt.value_or(scenario.time_step_safety * rayleigh);
  const double largest = largest_bounding_radius(spec);
  const double area = scenario.box.lx * scenario.box.ly;
  const double solid_volume = count * 4.0 / 3.0 * std::numbers::pi * std::pow(spec.mean_radius, 3);
  plan.layer_height = std::max(solid_volume / (spec.insertion_fraction * area), 2.5 * largest);

  // The plate's travel: from the top of the deposit (+ start_gap) to the target thickness, or for a
  // pressure target to random close packing (64 % solid); back up by a fraction of it.
  const double start = plan.layer_height + calendering.start_gap;
  const double end = calendering.target_thickness.value_or(solid_volume / (0.64 * area));
  const double travel = std::max(start - end, 0.0);
  const double load_speed =
      calendering.approach_speed > 0.0 ? std::min(calendering.approach_speed, calendering.speed) : calendering.speed;
  const double hold = calendering.hold_time_limit();
  const double relax = calendering.relax_time_limit();
  const Phase phases[] = {
      {"settling", "settle.time, settle.max_time", scenario.settle.time > 0.0 ? scenario.settle.max_time : 0.0},
      {"loading",
       "the travel from the deposit's top (packing.insertion_fraction, calendering.start_gap) to the target at "
       "calendering.speed / approach_speed",
       travel / load_speed + 2.0 * calendering.ramp_time},
      {"hold", "calendering.hold_time, max_hold_time", hold + calendering.ramp_time},
      {"unloading", "calendering.lift_speed", 0.15 * travel / calendering.lift_speed + calendering.ramp_time},
      {"relaxation", "calendering.relax_time, max_relax_time", relax},
  };
  const Phase* longest = &phases[0];
  for (const Phase& phase : phases) {
    plan.simulated_time += phase.time;
    if (!(phase.time <= longest->time)) longest = &phase;
  }
  plan.steps = plan.simulated_time / plan.time_step;

  // The engine's dense cell grid spans the box and the layer with cells of the largest reach.
  const double skin = scenario.skin > 0.0 ? scenario.skin : 0.2 * spec.mean_radius;
  const double cell = 2.0 * largest + skin;
  plan.grid_cells = std::max(1.0, std::floor(scenario.box.lx / cell)) *
                    std::max(1.0, std::floor(scenario.box.ly / cell)) *
                    (std::floor(std::max(start, plan.layer_height) / cell) + 1.0);
  const double insertion_cells =
      std::floor(scenario.box.lx / (2.0 * largest)) * std::floor(scenario.box.ly / (2.0 * largest));
  plan.memory_bytes =
      count * (kBytesPerParticle + kPairsPerParticle * kBytesPerPair) + kBytesPerGridCell * plan.grid_cells;

  const OutputSpec& output = scenario.output;
  const double rows = plan.steps / static_cast<double>(output.csv_every) + 10.0;
  const double frames = output.vtk_every > 0 ? plan.steps / static_cast<double>(output.vtk_every) + 2.0 : 2.0;
  plan.output_bytes =
      rows * kCsvBytesPerRow + frames * count * kVtkBytesPerParticle * 2.0 + count * kCheckpointBytesPerParticle;

  const std::string dt_source =
      scenario.dt ? "time.dt"
                  : "safety x Rayleigh time of the smallest semi-axis " + approx(plan.smallest_semi_axis) +
                        " µm (material.youngs_modulus, packing.mean_radius, packing.aspect, packing.density, "
                        "time.mass_scaling)";
  const std::string steps_reason = "the " + std::string(longest->name) + " phase alone takes up to " +
                                   approx(longest->time) + " µs (" + longest->fields +
                                   ") at dt = " + approx(plan.time_step) + " µs (" + dt_source + ")";
  const auto finite_positive = [](double value) { return std::isfinite(value) && value > 0.0; };
  if (!finite_positive(plan.time_step))
    plan.impossible.push_back("the time step is " + approx(plan.time_step) + " µs (" + dt_source +
                              "): expected a finite number > 0");
  else if (!std::isfinite(plan.simulated_time) || !std::isfinite(plan.steps) || plan.steps > kImpossibleSteps)
    plan.impossible.push_back("the run would take " + approx(plan.steps) + " steps, more than " +
                              format_number(kImpossibleSteps) + " could ever finish: " + steps_reason);
  else if (plan.steps > kMaxPlannedSteps)
    plan.beyond_limits.push_back("the run plans up to " + approx(std::ceil(plan.steps)) +
                                 " steps, above the limit of " + format_number(kMaxPlannedSteps) + ": " + steps_reason);
  const std::string grid_fields = "box.size " + format_number(scenario.box.lx) + " x " +
                                  format_number(scenario.box.ly) + " µm and a layer up to " +
                                  approx(std::max(start, plan.layer_height)) +
                                  " µm high (packing.insertion_fraction, calendering.start_gap) in cells of " +
                                  approx(cell) + " µm (packing.mean_radius, packing.aspect, time.skin)";
  if (!std::isfinite(plan.grid_cells) || plan.grid_cells > kMaxGridCells || !std::isfinite(insertion_cells) ||
      insertion_cells > kMaxGridCells)
    plan.impossible.push_back("the cell grid would need " + approx(std::max(plan.grid_cells, insertion_cells)) +
                              " cells, beyond the 32-bit cell index (at most " + format_number(kMaxGridCells) +
                              "): " + grid_fields);
  else if (!std::isfinite(plan.memory_bytes))
    plan.impossible.push_back("the memory estimate is not finite (packing.count, " + grid_fields + ")");
  else if (plan.memory_bytes > kMaxPlannedMemoryBytes)
    plan.beyond_limits.push_back("the run needs about " + format_bytes(plan.memory_bytes) +
                                 " of memory, above the limit of " + format_bytes(kMaxPlannedMemoryBytes) + ": " +
                                 format_number(count) + " particles (packing.count) and " + approx(plan.grid_cells) +
                                 " grid cells (" + grid_fields + ")");
  if (std::isfinite(plan.output_bytes) && plan.output_bytes > kMaxPlannedOutputBytes)
    plan.beyond_limits.push_back("the run writes about " + format_bytes(plan.output_bytes) +
                                 " of output, above the limit of " + format_bytes(kMaxPlannedOutputBytes) +
                                 ": raise output.csv_every (" + std::to_string(output.csv_every) +
                                 ") or output.vtk_every (" + std::to_string(output.vtk_every) + ")");
  return plan;
}

std::string describe_plan(const RunPlan& plan) {
  return "dt = " + approx(plan.time_step) + " µs, at most " + approx(std::ceil(plan.steps)) + " steps (" +
         approx(plan.simulated_time) + " µs simulated), memory ~" + format_bytes(plan.memory_bytes) + ", output ~" +
         format_bytes(plan.output_bytes);
}

}  // namespace ellc::scenario
