#include "ellc/scenario/diagnostics.hpp"

#include <cmath>

namespace ellc::scenario {

using engine::kBottomWall;
using engine::kTopWall;
using engine::Simulation;

namespace {

// Σ m z: gravity acts along z, the one direction positions are never wrapped in.
double height_moment(const Simulation& sim) noexcept {
  const auto& p = sim.particles();
  double moment = 0.0;
  for (std::size_t slot = 0; slot < p.size(); ++slot) moment += p.mass[slot] * p.position[slot].z();
  return moment;
}

double share(double part, double whole) noexcept { return whole > 0.0 ? part / whole : 0.0; }

}  // namespace

DiagnosticScales diagnostic_scales(const Scenario& scenario) noexcept {
  return {2.0 * scenario.packing.mean_radius, scenario.material_density * scenario.mass_scaling};
}

double inertial_number(double plate_speed, double gap, double diameter, double density, double pressure) noexcept {
  if (!(pressure > 0.0) || !(gap > 0.0)) return 0.0;
  return std::abs(plate_speed) / gap * diameter * std::sqrt(density / pressure);
}

double inertial_number(const Simulation& sim, const DiagnosticScales& scales) noexcept {
  const double speed = sim.walls()[kTopWall].velocity - sim.walls()[kBottomWall].velocity;
  return inertial_number(speed, sim.gap(), scales.particle_diameter, scales.scaled_density,
                         sim.wall_pressure(kTopWall));
}

EnergyTerms energy_terms(const Simulation& sim) noexcept {
  return {sim.kinetic_energy(),      sim.contact_elastic_energy(), sim.spring_energy(),
          sim.plastic_dissipation(), sim.friction_dissipation(),   sim.damping_dissipation()};
}

void EnergyLedger::start(const Simulation& sim) noexcept {
  state_ = State{};
  state_.at_start = energy_terms(sim);
  height_moment_ = height_moment(sim);
  kinetic_ = state_.at_start.kinetic;
}

void EnergyLedger::restore(const State& state, const Simulation& sim) noexcept {
  state_ = state;
  height_moment_ = height_moment(sim);
  kinetic_ = sim.kinetic_energy();
}

// Gravity's work over the step: g_z Δ(Σ m z), exact for the constant gravity of the step. The
// drag −γ m v (and −γ I ω) takes 2 γ E_kin per unit time: the trapezoid of the step's two ends.
void EnergyLedger::after_step(const Simulation& sim) noexcept {
  const double moment = height_moment(sim);
  state_.gravity_work += sim.settings().gravity.z() * (moment - height_moment_);
  height_moment_ = moment;
  // Tracked every step (an O(N) sum, against the contacts' O(N · contacts) of the step), so that a
  // restarted run, which recomputes it from its checkpoint, continues with the same value.
  const double kinetic = sim.kinetic_energy();
  state_.drag_dissipation += sim.settings().drag_rate * sim.settings().dt * (kinetic_ + kinetic);
  kinetic_ = kinetic;
}

EnergyBalance EnergyLedger::balance(const Simulation& sim) const noexcept {
  EnergyBalance balance;
  balance.work_bottom_plate = sim.wall_work(kBottomWall);
  balance.work_top_plate = sim.wall_work(kTopWall);
  balance.gravity_work = state_.gravity_work;
  balance.now = energy_terms(sim);
  balance.drag_dissipation = state_.drag_dissipation;
  balance.residual =
      balance.work() - (balance.now.sum() - state_.at_start.sum() + balance.drag_dissipation);
  return balance;
}

Diagnostics diagnose(const Simulation& sim, const DiagnosticScales& scales, const EnergyLedger& ledger) noexcept {
  Diagnostics diagnostics;
  diagnostics.inertial_number = inertial_number(sim, scales);
  diagnostics.unbalanced_force_ratio = sim.unbalanced_force_ratio();
  diagnostics.energy = ledger.balance(sim);
  const EnergyTerms& now = diagnostics.energy.now;
  diagnostics.kinetic_over_elastic = share(now.kinetic, now.elastic + now.spring);
  return diagnostics;
}

LoadedState loaded_state(const Simulation& sim, const DiagnosticScales& scales, const EnergyLedger& ledger) noexcept {
  const Diagnostics diagnostics = diagnose(sim, scales, ledger);
  LoadedState loaded;
  loaded.recorded = true;
  loaded.unbalanced_force_ratio = diagnostics.unbalanced_force_ratio;
  loaded.kinetic_over_elastic = diagnostics.kinetic_over_elastic;
  loaded.validity = sim.validity(kValidityThreshold);
  return loaded;
}

ValidityShares validity_shares(const engine::ValidityReport& report) noexcept {
  return {share(static_cast<double>(report.pair_contacts_beyond), static_cast<double>(report.pair_contacts)),
          share(report.pair_force_beyond, report.pair_force),
          share(static_cast<double>(report.wall_contacts_beyond), static_cast<double>(report.wall_contacts)),
          share(report.wall_force_beyond, report.wall_force)};
}

}  // namespace ellc::scenario
