#pragma once
// The loading protocol of a scenario as a state machine over the simulation:
//   settle  gravity with drag until the packing is slow enough (or out of time)
//   load    top plate down: first the approach through the loose deposit (approach_speed until
//           approach_pressure), then calendering at `speed` to the target thickness or pressure
//   hold    plate at rest for hold_time
//   unload  plate up at lift_speed until it loses contact
//   done    plate at rest; the released thickness is recorded
// It only moves the walls and switches gravity and drag; it writes nothing (run_outputs.hpp).
// Its state is trivially copyable and goes verbatim into checkpoints (checkpoint.hpp).

#include <array>
#include <cstdint>
#include <optional>

#include "ellc/engine/simulation.hpp"
#include "ellc/scenario/scenario.hpp"

namespace ellc::scenario {

enum class Phase : std::uint8_t { settle, load, hold, unload, done };
[[nodiscard]] const char* phase_name(Phase phase) noexcept;

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

class LoadingProtocol {
 public:
  explicit LoadingProtocol(const Scenario& scenario);

  // A fresh run, before the simulation exists: gravity and drag of the settling into `settings`;
  // returns the walls (floor at z = 0, plate 2 r̂ above the highest particle). The state starts
  // in `settle`.
  [[nodiscard]] std::array<engine::Wall, 2> start(engine::EngineSettings& settings, const engine::ParticleSet& particles);
  // The first transition of a fresh run, before any step: `load` when there is no settling.
  [[nodiscard]] std::optional<Phase> initial_transition() const noexcept;
  // A restarted run: the state read from its checkpoint, and the simulation read with it.
  void restore(const ProtocolState& state, const engine::Simulation& sim);

  // After each step: tracks the maximum pressure and the end of the approach, and returns the
  // phase to enter now, if any (the caller records its sample first, then calls enter()).
  // Throws std::runtime_error when the plate reaches the thickness of the solid while loading.
  [[nodiscard]] std::optional<Phase> after_step(engine::Simulation& sim);
  // Moves the plate and switches the forces for `phase`, recording what the summary reports.
  void enter(engine::Simulation& sim, Phase phase);

  [[nodiscard]] const ProtocolState& state() const noexcept { return state_; }
  [[nodiscard]] bool done() const noexcept { return state_.phase == Phase::done; }
  [[nodiscard]] double progress(const engine::Simulation& sim) const noexcept;  // rough fraction done

 private:
  SettleSpec settle_;
  CalenderingSpec calendering_;
  engine::Box box_;
  double mean_radius_ = 0.0;   // packing's mean r̂, µm
  double solid_volume_ = 0.0;  // µm³: the load stops at the thickness of the solid
  double total_mass_ = 0.0;    // ng: settling ends on the rms speed sqrt(2 E_kin / M)
  ProtocolState state_;
};

}  // namespace ellc::scenario
