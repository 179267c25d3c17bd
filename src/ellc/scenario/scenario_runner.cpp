#include "ellc/scenario/scenario_runner.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <vector>

#include "ellc/engine/binary_io.hpp"
#include "ellc/scenario/packing.hpp"
#include "ellc/engine/time_step.hpp"
#include "ellc/scenario/vtk_writer.hpp"
#include "ellc/io/input_error.hpp"

namespace ellc::engine {

namespace {

constexpr std::uint64_t kCheckpointTag = 0x454c4c43'434b5031ULL;  // "ELLCCKP1"

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
}

std::string frame_path(const std::string& directory, std::uint64_t step) {
  char name[64];
  std::snprintf(name, sizeof name, "particles_%09llu.vtk", static_cast<unsigned long long>(step));
  return (std::filesystem::path(directory) / "vtk" / name).string();
}

std::string csv_header() {
  return "step,time,phase,plate_position,thickness,plate_pressure,bottom_pressure,porosity,coordination_number,"
         "contacts,wall_contacts,contacts_elastic,contacts_elastic_plastic,contacts_fully_plastic,"
         "contacts_unloading,contacts_no_force,kinetic_energy,plastic_dissipation";
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

}  // namespace

const char* phase_name(Phase phase) noexcept {
  switch (phase) {
    case Phase::settle: return "settle";
    case Phase::load: return "load";
    case Phase::hold: return "hold";
    case Phase::unload: return "unload";
    case Phase::done: return "done";
  }
  return "unknown";
}

std::uint64_t scenario_hash(const std::string& text) noexcept {
  std::uint64_t hash = 0xcbf29ce484222325ULL;
  for (unsigned char c : text) {
    hash ^= c;
    hash *= 0x100000001b3ULL;
  }
  return hash;
}

ScenarioRunner::~ScenarioRunner() = default;

ScenarioRunner::ScenarioRunner(Scenario scenario, RunOptions options)
    : scenario_(std::move(scenario)), options_(std::move(options)) {
  directory_ = options_.output_directory.empty() ? scenario_.output.directory : options_.output_directory;
  warnings_ = scenario_.warnings;
  const PackingSpec& spec = scenario_.packing;

  EngineSettings settings;
  settings.contact = scenario_.contact;
  settings.box = scenario_.box;
  settings.skin = scenario_.skin;
  settings.max_speed = scenario_.max_speed;
  settings.parallel_threshold = options_.parallel_threshold;

  if (!options_.restart_path.empty()) {
    std::ifstream in(options_.restart_path, std::ios::binary);
    if (!in) throw InputError(options_.restart_path, "cannot open the checkpoint for reading");
    std::uint64_t tag = 0, hash = 0;
    binary::get(in, tag);
    if (tag != kCheckpointTag) throw InputError(options_.restart_path, "not an ellc dem checkpoint");
    binary::get(in, hash);
    if (hash != scenario_hash(scenario_.text))
      throw InputError(options_.restart_path, "--restart", options_.restart_path,
                       "a checkpoint written by this same scenario file (" + scenario_.source +
                           " has changed since, or is another scenario)");
    protocol_fields([&in](auto& value) { binary::get(in, value); }, state_);
    binary::get(in, dt_estimate_);
    settings.dt = 1.0;  // overwritten by the stored state
    simulation_ = std::make_unique<Simulation>(settings, ParticleSet{}, std::array<Wall, 2>{});
    simulation_->read_state(in);
    solid_volume_ = simulation_->particles().total_volume();
    for (double mass : simulation_->particles().mass) total_mass_ += mass;
    open_outputs(true);
    return;
  }

  ParticleSet particles =
      generate_packing(spec, scenario_.box, 0.0, spec.spheres ? OverlapTest{} : ellipsoid_overlap_test());
  solid_volume_ = particles.total_volume();
  for (double mass : particles.mass) total_mass_ += mass;
  dt_estimate_ = stable_time_step(particles, spec.density, scenario_.contact.material, scenario_.time_step_safety);
  settings.dt = dt_estimate_;
  if (scenario_.dt) {
    if (*scenario_.dt > dt_estimate_) {
      const std::string message = "time.dt = " + format_number(*scenario_.dt) + " µs is above the stability estimate " +
                                  format_number(dt_estimate_) + " µs (" + format_number(scenario_.time_step_safety) +
                                  " x Rayleigh time of the smallest semi-axis)";
      if (!options_.force)
        throw InputError(scenario_.source, "time.dt", format_number(*scenario_.dt),
                         "a time step <= " + format_number(dt_estimate_) +
                             " µs (the stability estimate), or run with --force");
      warnings_.push_back(message + "; running anyway (--force)");
    }
    settings.dt = *scenario_.dt;
  }
  double top = 0.0;
  for (std::size_t slot = 0; slot < particles.size(); ++slot)
    top = std::max(top, particles.position[slot].z() + particles.bounding_radius[slot]);
  std::array<Wall, 2> walls;
  walls[kBottomWall] = Wall{0.0, 0.0, 1, Eigen::Vector3d::Zero()};
  walls[kTopWall] = Wall{top + 2.0 * spec.mean_radius, 0.0, -1, Eigen::Vector3d::Zero()};
  settings.gravity = Eigen::Vector3d(0.0, 0.0, -scenario_.settle.gravity);
  settings.drag_rate = scenario_.settle.drag_rate;
  simulation_ = std::make_unique<Simulation>(settings, std::move(particles), walls);
  state_.phase = Phase::settle;
  state_.phase_end_time = scenario_.settle.time;
  open_outputs(false);
  if (scenario_.settle.time <= 0.0) enter_phase(Phase::load);
}

void ScenarioRunner::open_outputs(bool restarted) {
  if (!options_.write_files) return;
  std::filesystem::create_directories(std::filesystem::path(directory_) / "vtk");
  const std::string csv_path = (std::filesystem::path(directory_) / "timeseries.csv").string();
  if (restarted) {
    truncate_csv(csv_path, simulation_->step_count());
    csv_.open(csv_path, std::ios::app);
  } else {
    // A fresh run replaces the frames of an earlier run in the same directory (ours only).
    for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(directory_) / "vtk")) {
      const std::string name = entry.path().filename().string();
      if (name.rfind("particles_", 0) == 0 && entry.path().extension() == ".vtk") std::filesystem::remove(entry.path());
    }
    csv_.open(csv_path, std::ios::trunc);
    csv_ << csv_header() << '\n';
  }
  if (!csv_) throw std::runtime_error("cannot open " + csv_path + " for writing");
  csv_.precision(10);
  if (!restarted) {
    record_sample();
    write_vtk_frame(frame_path(directory_, 0), *simulation_);
  }
}

void ScenarioRunner::enter_phase(Phase phase) {
  Simulation& sim = *simulation_;
  const CalenderingSpec& spec = scenario_.calendering;
  record_sample();
  switch (phase) {
    case Phase::load: {
      sim.settings().gravity = Eigen::Vector3d(0.0, 0.0, -spec.gravity);
      sim.settings().drag_rate = 0.0;
      sim.set_wall_position(kTopWall, sim.highest_point() + spec.start_gap);
      state_.approaching = spec.approach_speed > 0.0;
      sim.set_wall_velocity(kTopWall, -(state_.approaching ? spec.approach_speed : spec.speed));
      state_.load_start_gap = sim.gap();
      state_.press_start_gap = sim.gap();
      state_.load_start_time = sim.time();
      state_.plastic_at_load_start = sim.plastic_dissipation();
      break;
    }
    case Phase::hold:
      sim.set_wall_velocity(kTopWall, 0.0);
      state_.phase_end_time = sim.time() + spec.hold_time;
      break;
    case Phase::unload:
      state_.min_gap = sim.gap();
      state_.loaded_porosity = sim.porosity();
      state_.pressure_end_of_hold = sim.wall_pressure(kTopWall);
      sim.set_wall_velocity(kTopWall, spec.lift_speed);
      break;
    case Phase::done:
      sim.set_wall_velocity(kTopWall, 0.0);
      state_.final_gap = sim.gap();
      state_.final_porosity = sim.porosity();
      state_.done_step = sim.step_count();
      break;
    case Phase::settle: break;
  }
  state_.phase = phase;
}

void ScenarioRunner::after_step() {
  Simulation& sim = *simulation_;
  const CalenderingSpec& spec = scenario_.calendering;
  const double pressure = sim.wall_pressure(kTopWall);
  if (state_.phase != Phase::settle && pressure > state_.max_pressure) {
    state_.max_pressure = pressure;
    state_.gap_at_max_pressure = sim.gap();
  }
  switch (state_.phase) {
    case Phase::settle: {
      // Settled: past the shortest time and slow enough (checked every 50 steps), or out of time.
      const SettleSpec& settle = scenario_.settle;
      const double max_time = settle.max_time > 0.0 ? settle.max_time : 3.0 * settle.time;
      if (sim.time() < state_.phase_end_time || sim.step_count() % 50 != 0) break;
      const double rms_speed = std::sqrt(2.0 * sim.kinetic_energy() / total_mass_);
      if (rms_speed < settle.speed_tolerance || sim.time() >= max_time) enter_phase(Phase::load);
      break;
    }
    case Phase::load: {
      if (state_.approaching && pressure >= spec.approach_pressure) {
        state_.approaching = false;
        state_.press_start_gap = sim.gap();
        sim.set_wall_velocity(kTopWall, -spec.speed);
      }
      const bool thick_reached = spec.target_thickness && sim.gap() <= *spec.target_thickness;
      const bool pressure_reached = spec.target_pressure && pressure >= *spec.target_pressure;
      if (thick_reached || pressure_reached) {
        enter_phase(Phase::hold);
      } else if (sim.gap() * scenario_.box.lx * scenario_.box.ly <= solid_volume_) {
        throw std::runtime_error("the top plate reached the thickness of the solid (" + format_number(sim.gap()) +
                                 " µm) before the target pressure: lower calendering.target_pressure");
      }
      break;
    }
    case Phase::hold:
      if (sim.time() >= state_.phase_end_time) enter_phase(Phase::unload);
      break;
    case Phase::unload:
      if (sim.wall_contact_count(kTopWall) == 0 || pressure <= spec.release_fraction * state_.max_pressure)
        enter_phase(Phase::done);
      break;
    case Phase::done: break;
  }
}

void ScenarioRunner::record_sample() {
  if (!options_.write_files || !csv_.is_open()) return;
  const Simulation& sim = *simulation_;
  const ContactCounts counts = sim.contact_counts();
  const double count = static_cast<double>(std::max<std::size_t>(sim.particles().size(), 1));
  const auto regime = [&](Regime r) { return counts.by_regime[static_cast<std::size_t>(r)]; };
  csv_ << sim.step_count() << ',' << sim.time() << ',' << phase_name(state_.phase) << ','
       << sim.walls()[kTopWall].position << ',' << sim.gap() << ',' << sim.wall_pressure(kTopWall) << ','
       << sim.wall_pressure(kBottomWall) << ',' << sim.porosity() << ','
       << 2.0 * static_cast<double>(counts.particle_contacts) / count << ',' << counts.particle_contacts << ','
       << counts.wall_contacts << ',' << regime(Regime::elastic) << ',' << regime(Regime::elastic_plastic) << ','
       << regime(Regime::fully_plastic) << ',' << regime(Regime::unloading) << ',' << regime(Regime::separated)
       << ',' << sim.kinetic_energy() << ',' << sim.plastic_dissipation() << '\n';
}

void ScenarioRunner::advance(std::uint64_t max_steps) {
  const OutputSpec& output = scenario_.output;
  for (std::uint64_t taken = 0; taken < max_steps && !done(); ++taken) {
    try {
      simulation_->step();
    } catch (const RunawayError& error) {
      if (options_.write_files) {
        const std::string path = (std::filesystem::path(directory_) / "checkpoint_failure.bin").string();
        write_checkpoint(path);
        throw RunawayError(std::string(error.what()) + "; state written to " + path, error.particle_id(), error.step());
      }
      throw;
    }
    after_step();
    if (!options_.write_files) continue;
    const std::uint64_t step = simulation_->step_count();
    if (step % static_cast<std::uint64_t>(output.csv_every) == 0) record_sample();
    if (output.vtk_every > 0 && step % static_cast<std::uint64_t>(output.vtk_every) == 0)
      write_vtk_frame(frame_path(directory_, step), *simulation_);
    if (output.checkpoint_every > 0 && step % static_cast<std::uint64_t>(output.checkpoint_every) == 0)
      write_checkpoint((std::filesystem::path(directory_) / "checkpoint.bin").string());
    if (done()) {
      csv_.flush();
      if (output.vtk_every == 0 || step % static_cast<std::uint64_t>(output.vtk_every) != 0)
        write_vtk_frame(frame_path(directory_, step), *simulation_);
      write_checkpoint((std::filesystem::path(directory_) / "checkpoint.bin").string());
    }
  }
  if (csv_.is_open()) csv_.flush();
}

void ScenarioRunner::write_checkpoint(const std::string& path) const {
  const std::string temporary = path + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error("cannot open " + temporary + " for writing");
    binary::put(out, kCheckpointTag);
    binary::put(out, scenario_hash(scenario_.text));
    protocol_fields([&out](const auto& value) { binary::put(out, value); }, state_);
    binary::put(out, dt_estimate_);
    simulation_->write_state(out);
    if (!out) throw std::runtime_error("writing " + temporary + " failed");
  }
  std::filesystem::rename(temporary, path);
}

RunSummary ScenarioRunner::summary() const {
  const Simulation& sim = *simulation_;
  RunSummary summary;
  summary.particles = sim.particles().size();
  summary.steps = sim.step_count();
  summary.time = sim.time();
  summary.dt = sim.settings().dt;
  summary.dt_estimate = dt_estimate_;
  summary.max_pressure = state_.max_pressure;
  summary.loaded_thickness = state_.min_gap;
  summary.final_thickness = state_.final_gap;
  summary.springback_percent =
      state_.min_gap > 0.0 && done() ? 100.0 * (state_.final_gap - state_.min_gap) / state_.min_gap : 0.0;
  summary.loaded_porosity = state_.loaded_porosity;
  summary.final_porosity = state_.final_porosity;
  summary.plastic_dissipation = sim.plastic_dissipation();
  summary.plastic_dissipation_calendering =
      state_.phase == Phase::settle ? 0.0 : summary.plastic_dissipation - state_.plastic_at_load_start;
  summary.narrow_phase_failures = sim.contact_counts().narrow_phase_failures;
  summary.finished = done();
  return summary;
}

std::string ScenarioRunner::write_summary() const {
  const RunSummary s = summary();
  std::string path = (std::filesystem::path(directory_) / "summary.txt").string();
  std::ofstream out(path);
  out.precision(8);
  out << "# ellc dem summary: " << scenario_.source << "\n"
      << "finished = " << (s.finished ? "true" : "false") << "\n"
      << "particles = " << s.particles << "\nsteps = " << s.steps << "\ntime_us = " << s.time
      << "\ndt_us = " << s.dt << "\ndt_estimate_us = " << s.dt_estimate << "\nmax_pressure_MPa = " << s.max_pressure
      << "\nloaded_thickness_um = " << s.loaded_thickness << "\nfinal_thickness_um = " << s.final_thickness
      << "\nspringback_percent = " << s.springback_percent << "\nloaded_porosity = " << s.loaded_porosity
      << "\nfinal_porosity = " << s.final_porosity << "\nplastic_dissipation_pJ = " << s.plastic_dissipation
      << "\nplastic_dissipation_calendering_pJ = " << s.plastic_dissipation_calendering
      << "\nnarrow_phase_failures = " << s.narrow_phase_failures << "\n";
  return path;
}

double ScenarioRunner::progress() const noexcept {
  if (done()) return 1.0;
  const Simulation& sim = *simulation_;
  const CalenderingSpec& spec = scenario_.calendering;
  const double settle =
      state_.phase == Phase::settle ? std::max(scenario_.settle.time, sim.time()) : state_.load_start_time;
  // Expected load travel: to the target thickness, or for a pressure target to about random close
  // packing (64 % solid).
  const double start_gap = state_.phase == Phase::settle ? std::max(sim.highest_point(), 1e-9) : state_.load_start_gap;
  const double packed_gap = solid_volume_ / (0.64 * scenario_.box.lx * scenario_.box.ly);
  const double travel = spec.target_thickness ? std::max(start_gap - *spec.target_thickness, 1e-9)
                                              : std::max(start_gap - packed_gap, 0.1 * start_gap);
  // With an approach, all but the last ~6 % of the travel go at approach_speed.
  const double load = spec.approach_speed > 0.0 ? 0.94 * travel / spec.approach_speed + 0.06 * travel / spec.speed
                                                : travel / spec.speed;
  const double hold = spec.hold_time;
  const double unload = 0.15 * travel / spec.lift_speed;
  const double total = settle + load + hold + unload;
  double elapsed = 0.0;
  switch (state_.phase) {
    case Phase::settle: elapsed = sim.time(); break;
    case Phase::load: {
      double fraction = (state_.load_start_gap - sim.gap()) / travel;
      if (spec.target_pressure) fraction = std::max(fraction, sim.wall_pressure(kTopWall) / *spec.target_pressure);
      elapsed = settle + std::clamp(fraction, 0.0, 1.0) * load;
      break;
    }
    case Phase::hold: elapsed = settle + load + std::clamp(hold - (state_.phase_end_time - sim.time()), 0.0, hold); break;
    case Phase::unload:
      elapsed = settle + load + hold + std::clamp((sim.gap() - state_.min_gap) / spec.lift_speed, 0.0, 0.95 * unload);
      break;
    case Phase::done: return 1.0;
  }
  return std::clamp(elapsed / total, 0.0, 0.999);
}

}  // namespace ellc::engine
