#pragma once
// What a reviewer of a calendering run asks besides pressure and thickness, computed in one place
// for the time series, the summary and the protocol: is the loading quasi-static (inertial
// number, unbalanced-force ratio, kinetic over elastic energy), does the energy balance close,
// and how much of the loaded state rests on contacts beyond the law's range. Definitions and
// units: docs/engine.md, "Outputs".

#include <cstdint>

#include "ellc/engine/simulation.hpp"
#include "ellc/scenario/scenario.hpp"

namespace ellc::scenario {

// The scenario's constants the diagnostics need.
struct DiagnosticScales {
  double particle_diameter = 0.0;  // d = 2 r̂, r̂ the packing's mean radius (packing.mean_radius), µm
  double scaled_density = 0.0;     // ρ_s = material density × mass_scaling, ng/µm³
};
[[nodiscard]] DiagnosticScales diagnostic_scales(const Scenario& scenario) noexcept;

// I = γ̇ d sqrt(ρ_s/p) with γ̇ = |plate speed| / H (1/µs, H the plate gap), d in µm, ρ_s in
// ng/µm³ and p in MPa; 0 when p ≤ 0 or H ≤ 0. Quasi-static: I ≪ 10⁻³…10⁻².
[[nodiscard]] double inertial_number(double plate_speed, double gap, double diameter, double density,
                                     double pressure) noexcept;
// The same for the plates of `sim`: the speed of the top plate relative to the floor, the gap
// between them and the top plate's pressure.
[[nodiscard]] double inertial_number(const engine::Simulation& sim, const DiagnosticScales& scales) noexcept;

// The energies the engine reports, pJ: stored (kinetic, the law's elastic energy, the tangential
// springs) and dissipated since the start (plastic, friction, dashpots).
struct EnergyTerms {
  double kinetic = 0.0;
  double elastic = 0.0;
  double spring = 0.0;
  double plastic = 0.0;
  double friction = 0.0;
  double damping = 0.0;
  [[nodiscard]] double sum() const noexcept { return kinetic + elastic + spring + plastic + friction + damping; }
};
[[nodiscard]] EnergyTerms energy_terms(const engine::Simulation& sim) noexcept;

// The energy balance since the start of the run, pJ: what the plates and gravity put in equals
// the change of the stored energy plus what was dissipated; the residual is what is left over.
struct EnergyBalance {
  double work_bottom_plate = 0.0;  // Simulation::wall_work
  double work_top_plate = 0.0;
  double gravity_work = 0.0;       // Σ m g·Δx (settling; calendering gravity)
  EnergyTerms now;                 // the engine's terms, as reported
  double drag_dissipation = 0.0;   // the settling's viscous drag
  // work − (now − at the start of the run, + drag): the terms the packing started with (energy
  // of initial overlaps or velocities) are subtracted, so that they show no residual.
  double residual = 0.0;
  [[nodiscard]] double plate_work() const noexcept { return work_bottom_plate + work_top_plate; }
  [[nodiscard]] double work() const noexcept { return plate_work() + gravity_work; }
};

// The two terms the engine does not integrate itself (gravity's work and the drag's
// dissipation, summed step by step here) and the terms at the start of the run. `State` is
// what a checkpoint keeps; the rest is recomputed from the simulation.
class EnergyLedger {
 public:
  struct State {
    EnergyTerms at_start;
    double gravity_work = 0.0;
    double drag_dissipation = 0.0;
  };

  // A fresh run, before its first step.
  void start(const engine::Simulation& sim) noexcept;
  // A restarted run: the state its checkpoint kept, and the simulation read with it.
  void restore(const State& state, const engine::Simulation& sim) noexcept;
  // After every Simulation::step(), before the protocol changes gravity or drag for the next.
  void after_step(const engine::Simulation& sim) noexcept;

  [[nodiscard]] const State& state() const noexcept { return state_; }
  [[nodiscard]] EnergyBalance balance(const engine::Simulation& sim) const noexcept;

 private:
  State state_;
  double height_moment_ = 0.0;  // Σ m z at the last step
  double kinetic_ = 0.0;        // kinetic energy at the last step
};

// One row's worth: the diagnostics of the current state.
struct Diagnostics {
  double inertial_number = 0.0;
  double unbalanced_force_ratio = 0.0;  // Simulation::unbalanced_force_ratio()
  double kinetic_over_elastic = 0.0;    // E_kin / (E_law + E_spring); 0 when nothing is stored
  EnergyBalance energy;
};
[[nodiscard]] Diagnostics diagnose(const engine::Simulation& sim, const DiagnosticScales& scales,
                                   const EnergyLedger& ledger) noexcept;

// c_c/r̂ beyond which the paper's theory ends (finite deformation, Sec. 2.2); ValidityReport.
inline constexpr double kValidityThreshold = 0.16;

// The loaded state: the diagnostics when the hold ends (trivially copyable: kept in checkpoints).
struct LoadedState {
  bool recorded = false;
  double unbalanced_force_ratio = 0.0;
  double kinetic_over_elastic = 0.0;
  engine::ValidityReport validity;
};
[[nodiscard]] LoadedState loaded_state(const engine::Simulation& sim, const DiagnosticScales& scales,
                                       const EnergyLedger& ledger) noexcept;

// The shares of a ValidityReport beyond its threshold, in [0, 1] (0 when there is nothing).
struct ValidityShares {
  double pair_contacts = 0.0;
  double pair_force = 0.0;
  double wall_contacts = 0.0;
  double wall_force = 0.0;
};
[[nodiscard]] ValidityShares validity_shares(const engine::ValidityReport& report) noexcept;

// What a run keeps beside the protocol and the simulation (the checkpoint's last section).
struct RunRecord {
  EnergyLedger::State ledger;
  LoadedState loaded;
};

}  // namespace ellc::scenario
