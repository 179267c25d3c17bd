#pragma once
// What a scenario run writes into its output directory, apart from checkpoints (checkpoint.hpp):
// the time series timeseries.csv (one row every csv_every steps and at each phase change), the
// VTK frames vtk/particles_<step>.vtk and vtk/contacts_<step>.vtk (the first, every vtk_every
// steps, the last) and summary.txt. The PNG plot of the time series is drawn by the CLI
// (apps/ellc/dem_command.cpp).

#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include "ellc/engine/simulation.hpp"
#include "ellc/scenario/diagnostics.hpp"
#include "ellc/scenario/protocol_stages.hpp"
#include "ellc/scenario/scenario.hpp"

namespace ellc::scenario {

class RunOutputs {
 public:
  // Disabled (`enabled` false), it writes nothing at all: runs in memory (tests). `scales` are
  // the scenario's constants of the diagnostics columns.
  RunOutputs(std::string directory, const OutputSpec& spec, bool enabled, const DiagnosticScales& scales);

  // Creates the directory. A fresh run starts a new time series (header, the first row, frame 0)
  // and removes the frames an earlier run left there; a restart keeps the rows up to its step
  // and appends to them. `ledger`: the run's energy ledger, for the energy columns.
  void open(const engine::Simulation& sim, Phase phase, bool restarted, const EnergyLedger& ledger);
  // One row of the time series, labelled with `phase`.
  void record_sample(const engine::Simulation& sim, Phase phase, const EnergyLedger& ledger);
  // After a step: the row and the frame when their cadence says so, and the last frame once the
  // protocol is `done`. Returns true when a checkpoint is due (its cadence, or the end).
  [[nodiscard]] bool after_step(const engine::Simulation& sim, Phase phase, bool done, const EnergyLedger& ledger);
  void flush();

  [[nodiscard]] bool enabled() const noexcept { return enabled_; }
  [[nodiscard]] const std::string& directory() const noexcept { return directory_; }
  // `name` inside the output directory.
  [[nodiscard]] std::string file(const std::string& name) const;

 private:
  std::string directory_;
  OutputSpec spec_;
  bool enabled_;
  DiagnosticScales scales_;
  std::ofstream csv_;
};

struct RunSummary {
  std::size_t particles = 0;
  std::vector<std::size_t> particles_per_species;  // index = species; written when there are several
  std::uint64_t steps = 0;
  double time = 0.0;                // µs
  double dt = 0.0;                  // µs
  double dt_estimate = 0.0;         // µs
  double max_pressure = 0.0;        // MPa
  double loaded_thickness = 0.0;    // µm, plate gap at the end of the hold
  double final_thickness = 0.0;     // µm, plate gap when contact was lost
  double springback_percent = 0.0;  // 100 (final − loaded) / loaded
  double loaded_porosity = 0.0;
  double final_porosity = 0.0;
  double plastic_dissipation = 0.0;              // pJ, whole run
  double plastic_dissipation_calendering = 0.0;  // pJ, from the start of the load
  std::uint64_t narrow_phase_failures = 0;
  bool finished = false;
  // Where the loaded and released states were read (ProtocolState::Reading).
  double held_pressure = 0.0;       // MPa, top plate at the loaded reading
  double loaded_time = 0.0;         // µs
  double loaded_plate_speed = 0.0;  // µm/µs
  double released_time = 0.0;       // µs
  double released_unbalanced_force_ratio = 0.0;
  double released_pressure = 0.0;       // MPa, top plate at the released reading (release = servo: p_r)
  double released_plate_speed = 0.0;    // µm/µs
  double loaded_inertial_number = 0.0;  // I of the plate at each reading (diagnostics.hpp)
  double released_inertial_number = 0.0;
  // The energy balance at the end of the run (diagnostics.hpp), pJ.
  double plate_work = 0.0;  // work of both plates
  double gravity_work = 0.0;
  double energy_residual = 0.0;           // work − (change of stored energy + dissipated energy)
  double energy_residual_fraction = 0.0;  // residual / work (0 when no work was done)
  // Plastic dissipation over the plate work of the whole run (0 when no work was done): the share
  // of the work the law's plastic flattening takes (docs/engine.md, "What the law changes").
  [[nodiscard]] double plastic_share_of_plate_work() const noexcept {
    return plate_work > 0.0 ? plastic_dissipation / plate_work : 0.0;
  }
  // The loaded state, when the hold ended (diagnostics.hpp); `loaded_state_recorded` is false
  // before. The validity report counts contacts beyond c_c/r̂ = 0.16, with c_c of eq. (9) at δ_*
  // and r̂ the mean radius of the pair's smaller particle (the particle's own against a wall).
  bool loaded_state_recorded = false;
  double loaded_unbalanced_force_ratio = 0.0;
  double loaded_kinetic_over_elastic = 0.0;
  engine::ValidityReport loaded_validity;
  ValidityShares loaded_validity_shares;  // of loaded_validity, in [0, 1]
};

[[nodiscard]] RunSummary summarize(const engine::Simulation& sim, const ProtocolState& protocol, double dt_estimate,
                                   const EnergyLedger& ledger, const LoadedState& loaded);
// Warnings a reader of the results must see (the CLI prints them to stderr): more than half of
// the pair force, or of the force on the walls, at the loaded state rests on contacts beyond
// c_c/r̂ = 0.16; a loaded or released state read above I = 10⁻³ or an unbalanced-force ratio of
// 10⁻³ (kQuasiStaticLimit: not a static reading).
inline constexpr double kQuasiStaticLimit = 1e-3;
[[nodiscard]] std::vector<std::string> summary_warnings(const RunSummary& summary);
// summary.txt: `key = value` lines under a comment naming the scenario file.
void write_summary_file(const std::string& path, const std::string& scenario_source, const RunSummary& summary);
// The same lines to a stream (the ensemble reads its members' figures from them, ensemble.hpp).
void write_summary_lines(std::ostream& out, const std::string& scenario_source, const RunSummary& summary);

}  // namespace ellc::scenario
