#pragma once
// Runs a Scenario: generate the packing, settle it under gravity with drag, then calender it
// (top plate down under displacement control to a target thickness or pressure, hold, lift
// until the plate loses contact). Writes the time series, VTK frames, checkpoints and the
// summary into the output directory. The protocol state is part of the checkpoint, so a
// restarted run continues exactly where the interrupted one stood.

#include <cstdint>
#include <fstream>
#include <memory>
#include <optional>
#include <string>

#include "ellc/scenario/scenario.hpp"
#include "ellc/engine/simulation.hpp"

namespace ellc::engine {

enum class Phase : std::uint8_t { settle, load, hold, unload, done };
[[nodiscard]] const char* phase_name(Phase phase) noexcept;

struct RunOptions {
  std::string output_directory;  // overrides [output].directory when not empty
  std::string restart_path;      // checkpoint to continue from (empty: fresh run)
  bool force = false;            // accept a time step above the stability estimate
  bool write_files = true;       // CSV, VTK, checkpoints, summary (tests may switch off)
  std::size_t parallel_threshold = EngineSettings{}.parallel_threshold;
};

// The protocol's own state (trivially copyable: stored verbatim in checkpoints).
struct ProtocolState {
  Phase phase = Phase::settle;
  double phase_end_time = 0.0;        // settle and hold end at fixed times
  double load_start_gap = 0.0;
  double load_start_time = 0.0;       // µs: how long the settling took
  bool approaching = false;           // the plate still compacts the loose deposit (approach_speed)
  double press_start_gap = 0.0;       // plate gap when the approach ended
  double max_pressure = 0.0;          // top plate, MPa
  double gap_at_max_pressure = 0.0;
  double min_gap = 0.0;               // plate gap at the end of the hold (loaded thickness)
  double pressure_end_of_hold = 0.0;
  double final_gap = 0.0;             // plate gap when the plate lost contact (released thickness)
  double final_porosity = 0.0;
  double loaded_porosity = 0.0;
  std::uint64_t done_step = 0;
  double plastic_at_load_start = 0.0;  // pJ dissipated while settling
};

struct RunSummary {
  std::size_t particles = 0;
  std::uint64_t steps = 0;
  double time = 0.0;               // µs
  double dt = 0.0;                 // µs
  double dt_estimate = 0.0;        // µs
  double max_pressure = 0.0;       // MPa
  double loaded_thickness = 0.0;   // µm, plate gap at the end of the hold
  double final_thickness = 0.0;    // µm, plate gap when contact was lost
  double springback_percent = 0.0; // 100 (final − loaded) / loaded
  double loaded_porosity = 0.0;
  double final_porosity = 0.0;
  double plastic_dissipation = 0.0;  // pJ, whole run
  double plastic_dissipation_calendering = 0.0;  // pJ, from the start of the load
  std::uint64_t narrow_phase_failures = 0;
  bool finished = false;
};

class ScenarioRunner {
 public:
  // Builds the packing (or reads the checkpoint in options.restart_path). Throws InputError
  // for a time step above the estimate without options.force.
  ScenarioRunner(Scenario scenario, RunOptions options);
  ~ScenarioRunner();
  ScenarioRunner(const ScenarioRunner&) = delete;
  ScenarioRunner& operator=(const ScenarioRunner&) = delete;

  // Runs at most `max_steps` steps, or until the protocol is done. On a runaway particle it
  // writes checkpoint_failure.bin and rethrows.
  void advance(std::uint64_t max_steps);
  [[nodiscard]] bool done() const noexcept { return state_.phase == Phase::done; }

  [[nodiscard]] const Simulation& simulation() const noexcept { return *simulation_; }
  [[nodiscard]] const ProtocolState& state() const noexcept { return state_; }
  [[nodiscard]] const Scenario& scenario() const noexcept { return scenario_; }
  [[nodiscard]] RunSummary summary() const;
  [[nodiscard]] double progress() const noexcept;  // rough fraction done, for the progress bar
  [[nodiscard]] const std::string& output_directory() const noexcept { return directory_; }
  [[nodiscard]] const std::vector<std::string>& warnings() const noexcept { return warnings_; }

  // Writes the full state (protocol + simulation) to `path` (atomically: temp file + rename).
  void write_checkpoint(const std::string& path) const;
  // Writes summary.txt; returns its path.
  std::string write_summary() const;

 private:
  void after_step();
  void enter_phase(Phase phase);
  void record_sample();
  void open_outputs(bool restarted);

  Scenario scenario_;
  RunOptions options_;
  std::string directory_;
  std::unique_ptr<Simulation> simulation_;
  ProtocolState state_;
  double dt_estimate_ = 0.0;
  double solid_volume_ = 0.0;
  double total_mass_ = 0.0;
  std::vector<std::string> warnings_;
  std::ofstream csv_;
};

// FNV-1a of the scenario text: a checkpoint only restarts the scenario it came from.
[[nodiscard]] std::uint64_t scenario_hash(const std::string& text) noexcept;

}  // namespace ellc::engine
