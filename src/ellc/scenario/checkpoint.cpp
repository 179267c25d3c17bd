#include "ellc/scenario/checkpoint.hpp"

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "ellc/engine/binary_io.hpp"
#include "ellc/io/input_error.hpp"

namespace ellc::scenario {

using engine::EngineSettings;
using engine::ParticleSet;
using engine::Simulation;
using engine::Wall;
namespace binary = engine::binary;

namespace {

constexpr std::uint64_t kCheckpointTag = 0x454c4c43'434b5033ULL;  // "ELLCCKP3": readings with I (was 2)
constexpr std::uint64_t kRecordTag = 0x454c4c43'52554e31ULL;      // "ELLCRUN1"

// The protocol state field by field (no padding bytes in the file: equal runs, equal files).
template <typename Io, typename State>
void protocol_fields(Io&& io, State& state) {
  io(state.phase);
  io(state.phase_end_time);
  io(state.load_start_gap);
  io(state.load_start_time);
  io(state.approaching);
  io(state.press_start_gap);
  io(state.max_pressure);
  io(state.gap_at_max_pressure);
  io(state.min_gap);
  io(state.pressure_end_of_hold);
  io(state.final_gap);
  io(state.final_porosity);
  io(state.loaded_porosity);
  io(state.done_step);
  io(state.plastic_at_load_start);
  io(state.ramp_start);
  io(state.ramp_from);
  io(state.ramp_to);
  io(state.approach_average);
  io(state.hold_start_time);
  io(state.relax_start_time);
  for (auto* reading : {&state.loaded, &state.released}) {
    io(reading->time);
    io(reading->unbalanced_force_ratio);
    io(reading->plate_speed);
    io(reading->gap);
    io(reading->pressure);
    io(reading->inertial_number);
  }
}

// The run's record field by field, as the protocol state.
template <typename Io, typename Record>
void record_fields(Io&& io, Record& record) {
  auto& terms = record.ledger.at_start;
  io(terms.kinetic);
  io(terms.elastic);
  io(terms.spring);
  io(terms.plastic);
  io(terms.friction);
  io(terms.damping);
  io(record.ledger.gravity_work);
  io(record.ledger.drag_dissipation);
  auto& loaded = record.loaded;
  io(loaded.recorded);
  io(loaded.unbalanced_force_ratio);
  io(loaded.kinetic_over_elastic);
  auto& validity = loaded.validity;
  io(validity.threshold);
  io(validity.pair_contacts);
  io(validity.pair_contacts_beyond);
  io(validity.pair_force);
  io(validity.pair_force_beyond);
  io(validity.wall_contacts);
  io(validity.wall_contacts_beyond);
  io(validity.wall_force);
  io(validity.wall_force_beyond);
  io(validity.largest_ratio);
}

}  // namespace

std::uint64_t scenario_hash(const std::string& text) noexcept {
  std::uint64_t hash = 0xcbf29ce484222325ULL;
  for (unsigned char c : text) {
    hash ^= c;
    hash *= 0x100000001b3ULL;
  }
  return hash;
}

void write_checkpoint(const std::string& path, const Scenario& scenario, const ProtocolState& protocol,
                      double dt_estimate, const Simulation& simulation, const RunRecord& record) {
  const std::string temporary = path + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error("cannot open " + temporary + " for writing");
    binary::put(out, kCheckpointTag);
    binary::put(out, scenario_hash(scenario.text));
    protocol_fields([&out](const auto& value) { binary::put(out, value); }, protocol);
    binary::put(out, dt_estimate);
    simulation.write_state(out);
    binary::put(out, kRecordTag);
    record_fields([&out](const auto& value) { binary::put(out, value); }, record);
    if (!out) throw std::runtime_error("writing " + temporary + " failed");
  }
  std::filesystem::rename(temporary, path);
}

Checkpoint read_checkpoint(const std::string& path, const Scenario& scenario, EngineSettings settings) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "cannot open the checkpoint for reading");
  std::uint64_t tag = 0, hash = 0;
  binary::get(in, tag);
  if (tag != kCheckpointTag) throw InputError(path, "not an ellc dem checkpoint");
  binary::get(in, hash);
  if (hash != scenario_hash(scenario.text))
    throw InputError(path, "--restart", path,
                     "a checkpoint written by this same scenario file (" + scenario.source +
                         " has changed since, or is another scenario)");
  Checkpoint checkpoint;
  protocol_fields([&in](auto& value) { binary::get(in, value); }, checkpoint.protocol);
  binary::get(in, checkpoint.dt_estimate);
  settings.dt = 1.0;  // overwritten by the stored state
  checkpoint.simulation = std::make_unique<Simulation>(settings, ParticleSet{}, std::array<Wall, 2>{});
  checkpoint.simulation->read_state(in);
  if (in.peek() != std::char_traits<char>::eof()) {
    std::uint64_t record_tag = 0;
    binary::get(in, record_tag);
    if (record_tag != kRecordTag) throw InputError(path, "the checkpoint's run record is corrupt");
    RunRecord record;
    record_fields([&in](auto& value) { binary::get(in, value); }, record);
    checkpoint.record = record;
  }
  return checkpoint;
}

}  // namespace ellc::scenario
