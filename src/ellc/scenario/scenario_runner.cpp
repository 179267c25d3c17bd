#include "ellc/scenario/scenario_runner.hpp"

#include <limits>
#include <utility>

#include "ellc/engine/time_step.hpp"
#include "ellc/io/input_error.hpp"
#include "ellc/scenario/checkpoint.hpp"
#include "ellc/scenario/packing.hpp"
#include "ellc/scenario/state_analysis.hpp"

namespace ellc::scenario {

using engine::EngineSettings;
using engine::ParticleSet;
using engine::RunawayError;
using engine::Simulation;
using engine::Wall;

namespace {

std::string directory_for(const Scenario& scenario, const RunOptions& options) {
  return options.output_directory.empty() ? scenario.output.directory : options.output_directory;
}

}  // namespace

ScenarioRunner::~ScenarioRunner() = default;

ScenarioRunner::ScenarioRunner(Scenario scenario, RunOptions options)
    : scenario_(std::move(scenario)),
      options_(std::move(options)),
      protocol_(scenario_),
      scales_(diagnostic_scales(scenario_)),
      outputs_(directory_for(scenario_, options_), scenario_.output, options_.write_files, scales_),
      warnings_(scenario_.warnings) {
  EngineSettings settings;
  settings.contact = scenario_.contact;
  settings.box = scenario_.box;
  settings.skin = scenario_.skin;
  settings.max_speed = scenario_.max_speed;
  settings.parallel_threshold = options_.parallel_threshold;
  if (options_.restart_path.empty())
    build_packing(settings);
  else
    restore(settings);
}

void ScenarioRunner::restore(EngineSettings settings) {
  Checkpoint checkpoint = read_checkpoint(options_.restart_path, scenario_, std::move(settings));
  simulation_ = std::move(checkpoint.simulation);
  dt_estimate_ = checkpoint.dt_estimate;
  protocol_.restore(checkpoint.protocol, *simulation_);
  RunRecord record;
  if (checkpoint.record)
    record = *checkpoint.record;
  else
    warnings_.push_back(options_.restart_path +
                        " predates the run record: the energy columns assume a start at rest without overlaps and "
                        "no gravity or drag before the restart, and the loaded state is only reported if the "
                        "hold ends after it");
  ledger_.restore(record.ledger, *simulation_);
  loaded_ = record.loaded;
  outputs_.open(*simulation_, protocol_.state().phase, true, ledger_);
}

double packing_time_step(const ParticleSet& particles, const Scenario& scenario) {
  // Several species: the shortest estimate over them (each as if it held the smallest particle).
  const std::vector<SpeciesSpec> species = species_of(scenario.packing);
  const std::vector<Material> materials = engine::species_materials(scenario.contact);
  double estimate = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < species.size(); ++k)
    estimate = std::min(
        estimate, engine::stable_time_step(particles, species[k].density, materials[k], scenario.time_step_safety));
  return estimate;
}

void ScenarioRunner::build_packing(EngineSettings settings) {
  const PackingSpec& spec = scenario_.packing;
  ParticleSet particles =
      generate_packing(spec, scenario_.box, 0.0, spec.spheres ? OverlapTest{} : ellipsoid_overlap_test());
  dt_estimate_ = packing_time_step(particles, scenario_);
  settings.dt = dt_estimate_;
  if (scenario_.dt) {
    if (*scenario_.dt > dt_estimate_) {
      const std::string message = "time.dt = " + format_number(*scenario_.dt) + " µs is above the stability estimate " +
                                  format_number(dt_estimate_) + " µs (" + format_number(scenario_.time_step_safety) +
                                  " x Rayleigh time of the smallest semi-axis)";
      if (!options_.force)
        throw InputError(
            scenario_.source, "time.dt", format_number(*scenario_.dt),
            "a time step <= " + format_number(dt_estimate_) + " µs (the stability estimate), or run with --force");
      warnings_.push_back(message + "; running anyway (--force)");
    }
    settings.dt = *scenario_.dt;
  }
  const std::array<Wall, 2> walls = protocol_.start(settings, particles);
  simulation_ = std::make_unique<Simulation>(settings, std::move(particles), walls);
  ledger_.start(*simulation_);
  outputs_.open(*simulation_, protocol_.state().phase, false, ledger_);
  if (const auto first = protocol_.initial_transition()) enter(*first);
}

// The row at a phase change shows the state just before it, labelled with the phase it ends.
// The end of the hold is the loaded state the summary reports.
void ScenarioRunner::enter(Phase phase) {
  outputs_.record_sample(*simulation_, protocol_.state().phase, ledger_);
  if (protocol_.state().phase == Phase::hold && phase != Phase::hold) {
    loaded_ = scenario::loaded_state(*simulation_, scales_, ledger_);
    if (scenario_.analysis) loaded_packing_ = packing_of(*simulation_);
  }
  protocol_.enter(*simulation_, phase);
}

void ScenarioRunner::advance(std::uint64_t max_steps) { advance(max_steps, {}); }

std::uint64_t ScenarioRunner::advance(std::uint64_t max_steps, const std::function<bool(const ScenarioRunner&)>& stop) {
  std::uint64_t taken = 0;
  while (taken < max_steps && !done()) {
    ++taken;
    try {
      simulation_->step();
    } catch (const RunawayError& error) {
      if (outputs_.enabled()) {
        const std::string path = outputs_.file("checkpoint_failure.bin");
        write_checkpoint(path);
        throw RunawayError(std::string(error.what()) + "; state written to " + path, error.particle_id(), error.step());
      }
      throw;
    }
    ledger_.after_step(*simulation_);
    std::optional<Phase> next;
    try {
      next = protocol_.after_step(*simulation_);
    } catch (const ProtocolError& error) {
      outputs_.record_sample(*simulation_, protocol_.state().phase, ledger_);
      outputs_.flush();
      if (outputs_.enabled()) {
        const std::string path = outputs_.file("checkpoint_failure.bin");
        write_checkpoint(path);
        throw ProtocolError(std::string(error.what()) + "; outputs kept, state written to " + path);
      }
      throw;
    }
    if (next) enter(*next);
    if (outputs_.after_step(*simulation_, protocol_.state().phase, done(), ledger_))
      write_checkpoint(outputs_.file("checkpoint.bin"));
    if (stop && stop(*this)) break;
  }
  outputs_.flush();
  return taken;
}

void ScenarioRunner::write_checkpoint(const std::string& path) const {
  scenario::write_checkpoint(path, scenario_, protocol_.state(), dt_estimate_, *simulation_,
                             RunRecord{ledger_.state(), loaded_});
}

Diagnostics ScenarioRunner::diagnostics() const noexcept { return diagnose(*simulation_, scales_, ledger_); }

RunSummary ScenarioRunner::summary() const {
  return summarize(*simulation_, protocol_.state(), dt_estimate_, ledger_, loaded_);
}

std::string ScenarioRunner::write_summary() const {
  std::string path = outputs_.file("summary.txt");  // not const: the return moves it
  write_summary_file(path, scenario_.source, summary());
  return path;
}

double ScenarioRunner::progress() const noexcept { return protocol_.progress(*simulation_); }

}  // namespace ellc::scenario
