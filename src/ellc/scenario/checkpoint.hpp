#pragma once
// The checkpoint file of `ellc dem`: a tag, the hash of the scenario text, the protocol state,
// the time-step estimate, then the simulation's own state (Simulation::write_state), then the
// run's record (diagnostics.hpp: the energy ledger and the loaded state) under a tag of its own.
// A restart from it continues the interrupted run bit for bit, and only for the scenario that
// wrote it. A checkpoint written before the record existed ends after the simulation; it still
// restarts, without the record.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "ellc/engine/simulation.hpp"
#include "ellc/scenario/diagnostics.hpp"
#include "ellc/scenario/protocol_stages.hpp"
#include "ellc/scenario/scenario.hpp"

namespace ellc::scenario {

// FNV-1a of the scenario text: a checkpoint only restarts the scenario it came from.
[[nodiscard]] std::uint64_t scenario_hash(const std::string& text) noexcept;

// Writes atomically (a temporary file, then a rename).
void write_checkpoint(const std::string& path, const Scenario& scenario, const ProtocolState& protocol,
                      double dt_estimate, const engine::Simulation& simulation, const RunRecord& record);

struct Checkpoint {
  ProtocolState protocol;
  double dt_estimate = 0.0;  // µs
  std::unique_ptr<engine::Simulation> simulation;
  std::optional<RunRecord> record;  // empty: a checkpoint from before the record existed
};

// Throws InputError for a file that cannot be read, is no checkpoint, or comes from another
// scenario. `settings` supplies what the stored state does not hold (material, box, ...).
[[nodiscard]] Checkpoint read_checkpoint(const std::string& path, const Scenario& scenario, engine::EngineSettings settings);

}  // namespace ellc::scenario
