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

constexpr std::uint64_t kCheckpointTag = 0x454c4c43'434b5032ULL;  // "ELLCCKP2": ramps and readings (was 1)

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
  }
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
                      double dt_estimate, const Simulation& simulation) {
  const std::string temporary = path + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error("cannot open " + temporary + " for writing");
    binary::put(out, kCheckpointTag);
    binary::put(out, scenario_hash(scenario.text));
    protocol_fields([&out](const auto& value) { binary::put(out, value); }, protocol);
    binary::put(out, dt_estimate);
    simulation.write_state(out);
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
  return checkpoint;
}

}  // namespace ellc::scenario
