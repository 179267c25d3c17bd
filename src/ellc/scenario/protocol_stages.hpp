#pragma once
// The loading protocol of a scenario as a state machine over the simulation:
//   settle  gravity with drag until the packing is slow enough (or out of time)
//   load    top plate down: first the approach through the loose deposit (approach_speed until
//           approach_pressure), then calendering at `speed` to the target thickness or pressure
//   hold    plate at rest (or servo-held at the target pressure) for hold_time, then until the
//           unbalanced-force ratio is below equilibrium_ratio: the loaded state is read there
//   unload  plate up at lift_speed until it loses contact, or (release = servo) until its
//           pressure has come down to the residual p_r = release_pressure_fraction × held pressure
//   relax   (relax_time > 0) plate at rest, away, until the layer is at rest: the released state;
//           or (release = servo) the servo holds p_r until the unbalanced-force ratio is below
//           equilibrium_ratio: the released state is read there, the plate still on the layer
//   done    plate at rest; the released thickness is recorded
// Plate velocity changes are half-cosine ramps over ramp_time.
// It only moves the walls and switches gravity and drag; it writes nothing (run_outputs.hpp).
// Its state is trivially copyable and goes verbatim into checkpoints (checkpoint.hpp).

#include <array>
#include <cstdint>
#include <optional>
#include <stdexcept>

#include "ellc/engine/simulation.hpp"
#include "ellc/scenario/diagnostics.hpp"
#include "ellc/scenario/scenario.hpp"

namespace ellc::scenario {

// `relax` (after unload) lets the released layer come to rest before it is read.
enum class Phase : std::uint8_t { settle, load, hold, unload, done, relax };
[[nodiscard]] const char* phase_name(Phase phase) noexcept;

// The protocol's own state (trivially copyable: stored verbatim in checkpoints).
struct ProtocolState {
  Phase phase = Phase::settle;
  double phase_end_time = 0.0;  // settle and hold end at fixed times
  double load_start_gap = 0.0;
  double load_start_time = 0.0;  // µs: how long the settling took
  bool approaching = false;      // the plate still compacts the loose deposit (approach_speed)
  double press_start_gap = 0.0;  // plate gap when the approach ended
  double max_pressure = 0.0;     // top plate, MPa
  double gap_at_max_pressure = 0.0;
  double min_gap = 0.0;  // plate gap at the end of the hold (loaded thickness)
  double pressure_end_of_hold = 0.0;
  double final_gap = 0.0;  // plate gap when the plate lost contact (released thickness)
  double final_porosity = 0.0;
  double loaded_porosity = 0.0;
  std::uint64_t done_step = 0;
  double plastic_at_load_start = 0.0;  // pJ dissipated while settling
  // The plate's velocity ramp: from ramp_from at ramp_start to ramp_to after ramp_time.
  double ramp_start = 0.0;
  double ramp_from = 0.0;
  double ramp_to = 0.0;
  double approach_average = 0.0;  // MPa, the averaged top pressure of the approach
  double hold_start_time = 0.0;
  double relax_start_time = 0.0;
  // Where the loaded (end of hold) and released (end of relaxation) states were read.
  struct Reading {
    double time = 0.0;
    double unbalanced_force_ratio = 1.0;
    double plate_speed = 0.0;  // µm/µs, |v| of the top plate
    double gap = 0.0;
    double pressure = 0.0;         // MPa, top plate
    double inertial_number = 0.0;  // diagnostics.hpp, of the plate's speed at the reading
  };
  Reading loaded;
  Reading released;
};

// The protocol cannot go on: a target it cannot reach, or an equilibrium it did not reach in its
// time. The runner writes checkpoint_failure.bin and the outputs so far before passing it on.
class ProtocolError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class LoadingProtocol {
 public:
  explicit LoadingProtocol(const Scenario& scenario);

  // A fresh run, before the simulation exists: gravity and drag of the settling into `settings`;
  // returns the walls (floor at z = 0, plate 2 r̂ above the highest particle). The state starts
  // in `settle`.
  [[nodiscard]] std::array<engine::Wall, 2> start(engine::EngineSettings& settings,
                                                  const engine::ParticleSet& particles);
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
  DiagnosticScales scales_;    // for the inertial number of the readings
  ProtocolState state_;

  void set_plate_velocity(engine::Simulation& sim, double velocity);  // starts a ramp to it
  void apply_ramp(engine::Simulation& sim) const;
  [[nodiscard]] ProtocolState::Reading reading(const engine::Simulation& sim) const;
  // release = servo: the residual pressure p_r (MPa), and the plate speed towards it, bounded by
  // the lift's ramp; true when the pressure is within release_tolerance of p_r.
  [[nodiscard]] double release_pressure() const noexcept;
  bool servo_release_step(engine::Simulation& sim, double pressure) const;
};

}  // namespace ellc::scenario
