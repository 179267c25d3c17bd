#pragma once
// Runs a Scenario: builds the packing (or reads a checkpoint), then steps the simulation while
// the loading protocol (protocol_stages.hpp: settle, load, hold, unload) drives the plate and
// the outputs (run_outputs.hpp, checkpoint.hpp) record it. The protocol state is part of the
// checkpoint, so a restarted run continues exactly where the interrupted one stood.

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ellc/engine/simulation.hpp"
#include "ellc/microstructure/packing.hpp"
#include "ellc/scenario/diagnostics.hpp"
#include "ellc/scenario/protocol_stages.hpp"
#include "ellc/scenario/run_outputs.hpp"
#include "ellc/scenario/scenario.hpp"

namespace ellc::scenario {

struct RunOptions {
  std::string output_directory;  // overrides [output].directory when not empty
  std::string restart_path;      // checkpoint to continue from (empty: fresh run)
  bool force = false;            // accept a time step above the stability estimate
  bool write_files = true;       // CSV, VTK, checkpoints, summary (tests may switch off)
  std::size_t parallel_threshold = engine::EngineSettings{}.parallel_threshold;
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
  // The same, and stops early after the first step at which `stop` returns true (the Python
  // module's run_until: a phase, a time). Returns the number of steps taken. Staged runs equal
  // one run: the step, the outputs and the checkpoints do not depend on where a call ends.
  std::uint64_t advance(std::uint64_t max_steps, const std::function<bool(const ScenarioRunner&)>& stop);
  [[nodiscard]] bool done() const noexcept { return protocol_.done(); }

  [[nodiscard]] const engine::Simulation& simulation() const noexcept { return *simulation_; }
  [[nodiscard]] const ProtocolState& state() const noexcept { return protocol_.state(); }
  [[nodiscard]] const Scenario& scenario() const noexcept { return scenario_; }
  // The diagnostics of the current state (diagnostics.hpp), and the state when the hold ended.
  [[nodiscard]] Diagnostics diagnostics() const noexcept;
  [[nodiscard]] const LoadedState& loaded_state() const noexcept { return loaded_; }
  // With [analysis]: the packing at the end of the hold (state_analysis.hpp), for its
  // microstructure analysis; empty before the hold ended in this process (also after a restart).
  [[nodiscard]] const std::optional<microstructure::Packing>& loaded_packing() const noexcept {
    return loaded_packing_;
  }
  [[nodiscard]] RunSummary summary() const;
  [[nodiscard]] double progress() const noexcept;  // rough fraction done, for the progress bar
  [[nodiscard]] const std::string& output_directory() const noexcept { return outputs_.directory(); }
  [[nodiscard]] const std::vector<std::string>& warnings() const noexcept { return warnings_; }

  // Writes the full state (protocol + simulation) to `path` (atomically: temp file + rename).
  void write_checkpoint(const std::string& path) const;
  // Writes summary.txt; returns its path.
  std::string write_summary() const;

 private:
  void build_packing(engine::EngineSettings settings);
  void restore(engine::EngineSettings settings);
  void enter(Phase phase);

  Scenario scenario_;
  RunOptions options_;
  LoadingProtocol protocol_;
  DiagnosticScales scales_;
  RunOutputs outputs_;
  EnergyLedger ledger_;
  LoadedState loaded_;
  std::optional<microstructure::Packing> loaded_packing_;
  std::unique_ptr<engine::Simulation> simulation_;
  double dt_estimate_ = 0.0;
  std::vector<std::string> warnings_;
};

}  // namespace ellc::scenario
