#pragma once
// The checkpoint file of `ellc dem` (format 3, docs/engine.md "Checkpoint file"): a 32-byte header
// (magic "ELLCCKPT", format version, header size, payload length, CRC-32 of the payload), then the
// payload: the hash of the scenario text, the protocol state, the time-step estimate, the
// simulation's own state (Simulation::write_state) and the run's record (diagnostics.hpp: the
// energy ledger and the loaded state) under a tag of its own.
// A restart from it continues the interrupted run bit for bit, and only for the scenario that
// wrote it. The reader checks the header against the file's length before it allocates anything,
// the checksum before it parses, and the content (positive semi-axes, unit quaternions, unique ids,
// dt > 0, pairs that refer to existing particles) before it returns; a corrupt file is an
// InputError with the reason.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "ellc/engine/simulation.hpp"
#include "ellc/scenario/diagnostics.hpp"
#include "ellc/scenario/protocol_stages.hpp"
#include "ellc/scenario/scenario.hpp"

namespace ellc::scenario {

inline constexpr std::uint32_t kCheckpointFormatVersion = 3;
inline constexpr std::size_t kCheckpointHeaderSize = 32;

// FNV-1a of the scenario text: a checkpoint only restarts the scenario it came from.
[[nodiscard]] std::uint64_t scenario_hash(const std::string& text) noexcept;

// CRC-32 (IEEE 802.3, reflected polynomial 0xEDB88320: the value zlib's crc32() gives).
[[nodiscard]] std::uint32_t crc32(std::string_view bytes) noexcept;

// Writes atomically (a temporary file, then a rename).
void write_checkpoint(const std::string& path, const Scenario& scenario, const ProtocolState& protocol,
                      double dt_estimate, const engine::Simulation& simulation, const RunRecord& record);

struct Checkpoint {
  ProtocolState protocol;
  double dt_estimate = 0.0;  // µs
  std::unique_ptr<engine::Simulation> simulation;
  std::optional<RunRecord> record;  // always present in format 3
};

// Throws InputError for a file that cannot be read, is no checkpoint, is corrupt (the reason
// named), or comes from another scenario. `settings` supplies what the stored state does not hold
// (material, box, ...).
[[nodiscard]] Checkpoint read_checkpoint(const std::string& path, const Scenario& scenario,
                                         engine::EngineSettings settings);
// The same from the file's bytes; `source` names it in messages (the fuzz harness uses this).
[[nodiscard]] Checkpoint parse_checkpoint(std::string_view bytes, const std::string& source, const Scenario& scenario,
                                          engine::EngineSettings settings);

}  // namespace ellc::scenario
