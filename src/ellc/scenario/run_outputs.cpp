#include "ellc/scenario/run_outputs.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <initializer_list>
#include <stdexcept>
#include <utility>
#include <vector>

#include "ellc/io/input_error.hpp"
#include "ellc/io/toml_text.hpp"
#include "ellc/scenario/vtk_writer.hpp"

namespace ellc::scenario {

using engine::ContactCounts;
using engine::kBottomWall;
using engine::kTopWall;
using engine::Simulation;

namespace {

std::string frame_path(const std::string& directory, const char* what, std::uint64_t step) {
  char name[64];
  std::snprintf(name, sizeof name, "%s_%09llu.vtk", what, static_cast<unsigned long long>(step));
  return (std::filesystem::path(directory) / "vtk" / name).string();
}

// A frame: the particles and their contacts.
void write_frame(const std::string& directory, const Simulation& sim) {
  write_vtk_frame(frame_path(directory, "particles", sim.step_count()), sim);
  write_vtk_contacts(frame_path(directory, "contacts", sim.step_count()), sim);
}

std::string csv_header() {
  return "step,time,phase,plate_position,thickness,plate_pressure,bottom_pressure,porosity,coordination_number,"
         "contacts,wall_contacts,contacts_elastic,contacts_elastic_plastic,contacts_fully_plastic,"
         "contacts_unloading,contacts_no_force,kinetic_energy,plastic_dissipation,"
         "inertial_number,unbalanced_force_ratio,kinetic_over_elastic,work_bottom_plate,work_top_plate,gravity_work,"
         "elastic_energy,spring_energy,friction_dissipation,damping_dissipation,drag_dissipation,energy_residual";
}

// Keeps the header and the rows up to `step` (a restart continues the series from there).
void truncate_csv(const std::string& path, std::uint64_t step) {
  std::ifstream in(path);
  if (!in) return;
  std::vector<std::string> kept;
  std::string line;
  while (std::getline(in, line)) {
    if (kept.empty()) {
      kept.push_back(line);
      continue;
    }
    const auto comma = line.find(',');
    if (comma == std::string::npos) continue;
    if (std::stoull(line.substr(0, comma)) <= step) kept.push_back(line);
  }
  in.close();
  std::ofstream out(path, std::ios::trunc);
  for (const auto& row : kept) out << row << '\n';
}

bool due(std::uint64_t step, long every) { return every > 0 && step % static_cast<std::uint64_t>(every) == 0; }

}  // namespace

RunOutputs::RunOutputs(std::string directory, const OutputSpec& spec, bool enabled, const DiagnosticScales& scales)
    : directory_(std::move(directory)), spec_(spec), enabled_(enabled), scales_(scales) {}

std::string RunOutputs::file(const std::string& name) const {
  return (std::filesystem::path(directory_) / name).string();
}

void RunOutputs::open(const Simulation& sim, Phase phase, bool restarted, const EnergyLedger& ledger) {
  if (!enabled_) return;
  std::filesystem::create_directories(std::filesystem::path(directory_) / "vtk");
  const std::string csv_path = file("timeseries.csv");
  if (restarted) {
    truncate_csv(csv_path, sim.step_count());
    csv_.open(csv_path, std::ios::app);
  } else {
    // A fresh run replaces the frames of an earlier run in the same directory (ours only).
    for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(directory_) / "vtk")) {
      const std::string name = entry.path().filename().string();
      const bool ours = name.rfind("particles_", 0) == 0 || name.rfind("contacts_", 0) == 0;
      if (ours && entry.path().extension() == ".vtk") std::filesystem::remove(entry.path());
    }
    csv_.open(csv_path, std::ios::trunc);
    csv_ << csv_header() << '\n';
  }
  if (!csv_) throw std::runtime_error("cannot open " + csv_path + " for writing");
  csv_.precision(10);
  if (!restarted) {
    record_sample(sim, phase, ledger);
    write_frame(directory_, sim);
  }
}

void RunOutputs::record_sample(const Simulation& sim, Phase phase, const EnergyLedger& ledger) {
  if (!enabled_ || !csv_.is_open()) return;
  const ContactCounts counts = sim.contact_counts();
  const double count = static_cast<double>(std::max<std::size_t>(sim.particles().size(), 1));
  const auto regime = [&](Regime r) { return counts.by_regime[static_cast<std::size_t>(r)]; };
  csv_ << sim.step_count() << ',' << sim.time() << ',' << phase_name(phase) << ',' << sim.walls()[kTopWall].position
       << ',' << sim.gap() << ',' << sim.wall_pressure(kTopWall) << ',' << sim.wall_pressure(kBottomWall) << ','
       << sim.porosity() << ',' << 2.0 * static_cast<double>(counts.particle_contacts) / count << ','
       << counts.particle_contacts << ',' << counts.wall_contacts << ',' << regime(Regime::elastic) << ','
       << regime(Regime::elastic_plastic) << ',' << regime(Regime::fully_plastic) << ',' << regime(Regime::unloading)
       << ',' << regime(Regime::separated) << ',' << sim.kinetic_energy() << ',' << sim.plastic_dissipation();
  const Diagnostics d = diagnose(sim, scales_, ledger);
  const EnergyBalance& e = d.energy;
  csv_ << ',' << d.inertial_number << ',' << d.unbalanced_force_ratio << ',' << d.kinetic_over_elastic << ','
       << e.work_bottom_plate << ',' << e.work_top_plate << ',' << e.gravity_work << ',' << e.now.elastic << ','
       << e.now.spring << ',' << e.now.friction << ',' << e.now.damping << ',' << e.drag_dissipation << ','
       << e.residual << '\n';
}

bool RunOutputs::after_step(const Simulation& sim, Phase phase, bool done, const EnergyLedger& ledger) {
  if (!enabled_) return false;
  const std::uint64_t step = sim.step_count();
  if (step % static_cast<std::uint64_t>(spec_.csv_every) == 0) record_sample(sim, phase, ledger);
  if (due(step, spec_.vtk_every)) write_frame(directory_, sim);
  if (done) {
    csv_.flush();
    if (!due(step, spec_.vtk_every)) write_frame(directory_, sim);
  }
  return done || due(step, spec_.checkpoint_every);
}

void RunOutputs::flush() {
  if (csv_.is_open()) csv_.flush();
}

RunSummary summarize(const Simulation& sim, const ProtocolState& protocol, double dt_estimate,
                     const EnergyLedger& ledger, const LoadedState& loaded) {
  const bool done = protocol.phase == Phase::done;
  RunSummary summary;
  summary.particles = sim.particles().size();
  summary.particles_per_species.assign(engine::species_materials(sim.settings().contact).size(), 0);
  for (const std::uint16_t species : sim.particles().species) ++summary.particles_per_species[species];
  summary.steps = sim.step_count();
  summary.time = sim.time();
  summary.dt = sim.settings().dt;
  summary.dt_estimate = dt_estimate;
  summary.max_pressure = protocol.max_pressure;
  summary.loaded_thickness = protocol.min_gap;
  summary.final_thickness = protocol.final_gap;
  summary.springback_percent =
      protocol.min_gap > 0.0 && done ? 100.0 * (protocol.final_gap - protocol.min_gap) / protocol.min_gap : 0.0;
  summary.loaded_porosity = protocol.loaded_porosity;
  summary.final_porosity = protocol.final_porosity;
  summary.plastic_dissipation = sim.plastic_dissipation();
  summary.plastic_dissipation_calendering =
      protocol.phase == Phase::settle ? 0.0 : summary.plastic_dissipation - protocol.plastic_at_load_start;
  summary.narrow_phase_failures = sim.contact_counts().narrow_phase_failures;
  summary.finished = done;
  summary.held_pressure = protocol.loaded.pressure;
  summary.loaded_time = protocol.loaded.time;
  summary.loaded_plate_speed = protocol.loaded.plate_speed;
  summary.released_time = protocol.released.time;
  summary.released_unbalanced_force_ratio = protocol.released.unbalanced_force_ratio;
  summary.released_pressure = protocol.released.pressure;
  summary.released_plate_speed = protocol.released.plate_speed;
  summary.loaded_inertial_number = protocol.loaded.inertial_number;
  summary.released_inertial_number = protocol.released.inertial_number;
  const EnergyBalance energy = ledger.balance(sim);
  summary.plate_work = energy.plate_work();
  summary.gravity_work = energy.gravity_work;
  summary.energy_residual = energy.residual;
  summary.energy_residual_fraction = energy.work() != 0.0 ? energy.residual / energy.work() : 0.0;
  summary.loaded_state_recorded = loaded.recorded;
  summary.loaded_unbalanced_force_ratio = loaded.unbalanced_force_ratio;
  summary.loaded_kinetic_over_elastic = loaded.kinetic_over_elastic;
  summary.loaded_validity = loaded.validity;
  summary.loaded_validity_shares = validity_shares(loaded.validity);
  return summary;
}

std::vector<std::string> summary_warnings(const RunSummary& s) {
  std::vector<std::string> warnings;
  const auto not_static = [&warnings](const char* state, double inertial, double ratio) {
    if (inertial <= kQuasiStaticLimit && ratio <= kQuasiStaticLimit) return;
    warnings.push_back(std::string("the ") + state + " state was read at I = " + format_number(inertial) +
                       " and an unbalanced-force ratio of " + format_number(ratio) +
                       ", not both <= " + format_number(kQuasiStaticLimit) + ": its figures are not a static reading");
  };
  if (s.loaded_state_recorded) not_static("loaded", s.loaded_inertial_number, s.loaded_unbalanced_force_ratio);
  if (s.finished && s.loaded_state_recorded)
    not_static("released", s.released_inertial_number, s.released_unbalanced_force_ratio);
  if (!s.loaded_state_recorded) return warnings;
  const engine::ValidityReport& v = s.loaded_validity;
  const auto percent = [](double share) {
    char text[32];
    std::snprintf(text, sizeof text, "%.0f %%", 100.0 * share);
    return std::string(text);
  };
  const std::string beyond =
      " at the loaded state (end of the hold) rests on contacts beyond c_c/r^ = " + format_number(v.threshold) +
      ", where the law is outside its range";
  if (s.loaded_validity_shares.wall_force > 0.5)
    warnings.push_back(percent(s.loaded_validity_shares.wall_force) + " of the force on the plates" + beyond +
                       " (r^ the particle's mean radius); the plate pressure extrapolates the law");
  if (s.loaded_validity_shares.pair_force > 0.5)
    warnings.push_back(percent(s.loaded_validity_shares.pair_force) + " of the force between particles" + beyond +
                       " (r^ the mean radius of the smaller particle of each pair)");
  return warnings;
}

void write_summary_file(const std::string& path, const std::string& scenario_source, const RunSummary& s) {
  std::ofstream out(path);
  write_summary_lines(out, scenario_source, s);
}

void write_summary_lines(std::ostream& out, const std::string& scenario_source, const RunSummary& s) {
  // A TOML document: every real number in its shortest round-trip form with a decimal point
  // (toml_float), so that a reader gets the run's doubles exactly and as floats (0 would read as
  // an integer); counts are integers.
  const auto reals = [&out](std::initializer_list<std::pair<const char*, double>> figures) {
    for (const auto& [key, value] : figures) out << key << " = " << toml_float(value) << '\n';
  };
  const auto flag = [&out](const char* key, bool value) { out << key << " = " << (value ? "true" : "false") << '\n'; };
  out << "# ellc dem summary: " << scenario_source << "\n";
  flag("finished", s.finished);
  out << "particles = " << s.particles << "\nsteps = " << s.steps << '\n';
  reals({{"time_us", s.time},
         {"dt_us", s.dt},
         {"dt_estimate_us", s.dt_estimate},
         {"max_pressure_MPa", s.max_pressure},
         {"loaded_thickness_um", s.loaded_thickness},
         {"final_thickness_um", s.final_thickness},
         {"springback_percent", s.springback_percent},
         {"loaded_porosity", s.loaded_porosity},
         {"final_porosity", s.final_porosity},
         {"plastic_dissipation_pJ", s.plastic_dissipation},
         {"plastic_dissipation_calendering_pJ", s.plastic_dissipation_calendering}});
  out << "narrow_phase_failures = " << s.narrow_phase_failures << '\n';
  reals({{"plate_work_pJ", s.plate_work},
         {"plastic_share_of_plate_work", s.plastic_share_of_plate_work()},
         {"gravity_work_pJ", s.gravity_work},
         {"energy_residual_pJ", s.energy_residual},
         {"energy_residual_fraction", s.energy_residual_fraction},
         {"held_pressure_MPa", s.held_pressure},
         {"loaded_time_us", s.loaded_time},
         {"loaded_plate_speed_um_per_us", s.loaded_plate_speed},
         {"released_time_us", s.released_time},
         {"released_unbalanced_force_ratio", s.released_unbalanced_force_ratio},
         {"released_pressure_MPa", s.released_pressure},
         {"released_plate_speed_um_per_us", s.released_plate_speed},
         {"loaded_inertial_number", s.loaded_inertial_number},
         {"released_inertial_number", s.released_inertial_number}});
  const engine::ValidityReport& v = s.loaded_validity;
  const ValidityShares& share = s.loaded_validity_shares;
  out << "# the loaded state (end of the hold); validity: c_c at delta_* (eq. 9) over r^ = the mean radius of the\n"
      << "# pair's smaller particle (the particle's own against a wall), contacts beyond validity_threshold\n";
  flag("loaded_state_recorded", s.loaded_state_recorded);
  reals({{"loaded_unbalanced_force_ratio", s.loaded_unbalanced_force_ratio},
         {"loaded_kinetic_over_elastic", s.loaded_kinetic_over_elastic},
         {"validity_threshold", v.threshold}});
  out << "validity_r_hat = \"smaller_particle_of_the_pair\"\nloaded_pair_contacts = " << v.pair_contacts << '\n';
  reals({{"loaded_pair_contacts_beyond_fraction", share.pair_contacts},
         {"loaded_pair_force_beyond_fraction", share.pair_force}});
  out << "loaded_wall_contacts = " << v.wall_contacts << '\n';
  reals({{"loaded_wall_contacts_beyond_fraction", share.wall_contacts},
         {"loaded_wall_force_beyond_fraction", share.wall_force},
         {"loaded_largest_size_ratio", v.largest_ratio}});
  if (s.particles_per_species.size() > 1) {  // several species ([[species]], in their order)
    out << "# particles of each species ([[species]] in their order)\n";
    for (std::size_t k = 0; k < s.particles_per_species.size(); ++k)
      out << "species_" << k << "_particles = " << s.particles_per_species[k] << "\n";
  }
}

}  // namespace ellc::scenario
