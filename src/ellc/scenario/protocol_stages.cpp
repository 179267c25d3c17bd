#include "ellc/scenario/protocol_stages.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "ellc/engine/servo.hpp"
#include "ellc/geometry/ellipsoid.hpp"
#include "ellc/io/input_error.hpp"

namespace ellc::scenario {

using engine::EngineSettings;
using engine::kBottomWall;
using engine::kTopWall;
using engine::ParticleSet;
using engine::Simulation;
using engine::Wall;

namespace {

// The top plate's servo speed towards the particles (engine/servo.hpp), at its contacts' stiffness.
double plate_servo_speed(const Simulation& sim, const engine::PlateServo& servo, double pressure) {
  const auto& box = sim.settings().box;
  return engine::servo_speed(servo, pressure, sim.wall_stiffness(kTopWall) / (box.lx * box.ly), sim.settings().dt);
}

double summed_mass(const ParticleSet& particles) {
  double total = 0.0;
  for (double mass : particles.mass) total += mass;
  return total;
}

// The top of the layer: the highest point of any particle's surface (the plate gap at which a
// plate coming down would touch it).
double layer_top(const ParticleSet& particles) {
  double top = 0.0;
  for (std::size_t slot = 0; slot < particles.size(); ++slot)
    top =
        std::max(top, Ellipsoid(particles.semi_axes[slot], Pose{particles.position[slot], particles.orientation[slot]})
                          .axis_aligned_bounds()
                          .upper.z());
  return top;
}

std::size_t particles_above_plate(const Simulation& sim) noexcept {
  const double plate = sim.walls()[kTopWall].position;
  std::size_t above = 0;
  for (const auto& centre : sim.particles().position) above += centre.z() > plate ? 1 : 0;
  return above;
}

}  // namespace

const char* phase_name(Phase phase) noexcept {
  switch (phase) {
    case Phase::settle: return "settle";
    case Phase::load: return "load";
    case Phase::hold: return "hold";
    case Phase::unload: return "unload";
    case Phase::done: return "done";
    case Phase::relax: return "relax";
  }
  return "unknown";
}

LoadingProtocol::LoadingProtocol(const Scenario& scenario)
    : settle_(scenario.settle),
      calendering_(scenario.calendering),
      box_(scenario.box),
      mean_radius_(scenario.packing.mean_radius),
      scales_(diagnostic_scales(scenario)) {}

std::array<Wall, 2> LoadingProtocol::start(EngineSettings& settings, const ParticleSet& particles) {
  solid_volume_ = particles.total_volume();
  total_mass_ = summed_mass(particles);
  double top = 0.0;
  for (std::size_t slot = 0; slot < particles.size(); ++slot)
    top = std::max(top, particles.position[slot].z() + particles.bounding_radius[slot]);
  std::array<Wall, 2> walls;
  walls[kBottomWall] = Wall{0.0, 0.0, 1, Eigen::Vector3d::Zero()};
  walls[kTopWall] = Wall{top + 2.0 * mean_radius_, 0.0, -1, Eigen::Vector3d::Zero()};
  settings.gravity = Eigen::Vector3d(0.0, 0.0, -settle_.gravity);
  settings.drag_rate = settle_.drag_rate;
  state_ = ProtocolState{};
  state_.phase = Phase::settle;
  state_.phase_end_time = settle_.time;
  return walls;
}

std::optional<Phase> LoadingProtocol::initial_transition() const noexcept {
  if (state_.phase == Phase::settle && settle_.time <= 0.0) return Phase::load;
  return std::nullopt;
}

void LoadingProtocol::restore(const ProtocolState& state, const Simulation& sim) {
  state_ = state;
  solid_volume_ = sim.particles().total_volume();
  total_mass_ = summed_mass(sim.particles());
}

void LoadingProtocol::set_plate_velocity(Simulation& sim, double velocity) {
  state_.ramp_from = sim.walls()[kTopWall].velocity;
  state_.ramp_to = velocity;
  state_.ramp_start = sim.time();
  apply_ramp(sim);
}

// v(t) = v₀ + (v₁ − v₀) (1 − cos(π s))/2, s = (t − t₀)/ramp_time: no jump in velocity, and its
// rate of change starts and ends at zero, so no stress wave is launched by the change.
void LoadingProtocol::apply_ramp(Simulation& sim) const {
  const double ramp = calendering_.ramp_time;
  const double s = ramp > 0.0 ? std::clamp((sim.time() - state_.ramp_start) / ramp, 0.0, 1.0) : 1.0;
  const double weight = s >= 1.0 ? 1.0 : 0.5 * (1.0 - std::cos(std::numbers::pi * s));
  sim.set_wall_velocity(kTopWall, state_.ramp_from + (state_.ramp_to - state_.ramp_from) * weight);
}

ProtocolState::Reading LoadingProtocol::reading(const Simulation& sim) const {
  return {sim.time(), sim.unbalanced_force_ratio(), std::abs(sim.walls()[kTopWall].velocity),
          sim.gap(),  sim.wall_pressure(kTopWall),  inertial_number(sim, scales_)};
}

double LoadingProtocol::release_pressure() const noexcept {
  return calendering_.release_pressure_fraction * state_.loaded.pressure;
}

// The plate follows the pressure down to p_r in proportion to the error relative to the held
// pressure (not to p_r: the same loop gain as the hold's servo, which the layer's thickness mode
// can follow), never faster than the lift's ramp allows, and stands still within the tolerance.
bool LoadingProtocol::servo_release_step(Simulation& sim, double pressure) const {
  const CalenderingSpec& spec = calendering_;
  const double target = release_pressure();
  const bool within = std::abs(pressure - target) <= spec.release_tolerance * target;
  const double envelope = std::abs(sim.walls()[kTopWall].velocity);  // the ramp's speed, set just before
  const engine::PlateServo servo_law{target, state_.loaded.pressure, spec.lift_speed, spec.servo_gain,
                                     spec.release_tolerance};
  const double servo = within ? 0.0 : -plate_servo_speed(sim, servo_law, pressure);
  sim.set_wall_velocity(kTopWall, state_.phase == Phase::unload ? std::clamp(servo, -envelope, envelope) : servo);
  return within;
}

void LoadingProtocol::enter(Simulation& sim, Phase phase) {
  const CalenderingSpec& spec = calendering_;
  switch (phase) {
    case Phase::load: {
      sim.settings().gravity = Eigen::Vector3d(0.0, 0.0, -spec.gravity);
      sim.settings().drag_rate = 0.0;
      sim.set_wall_position(kTopWall, sim.highest_point() + spec.start_gap);
      state_.approaching = spec.approach_speed > 0.0;
      set_plate_velocity(sim, -(state_.approaching ? spec.approach_speed : spec.speed));
      state_.load_start_gap = sim.gap();
      state_.press_start_gap = sim.gap();
      state_.load_start_time = sim.time();
      state_.plastic_at_load_start = sim.plastic_dissipation();
      break;
    }
    case Phase::hold:
      if (!spec.servo_hold) set_plate_velocity(sim, 0.0);
      sim.settings().drag_rate = spec.rest_drag_rate;
      state_.hold_start_time = sim.time();
      state_.phase_end_time = sim.time() + spec.hold_time;
      break;
    case Phase::unload:
      state_.loaded = reading(sim);
      state_.min_gap = sim.gap();
      state_.loaded_porosity = sim.porosity();
      state_.pressure_end_of_hold = sim.wall_pressure(kTopWall);
      sim.settings().drag_rate = 0.0;
      set_plate_velocity(sim, spec.lift_speed);
      break;
    case Phase::relax:
      // The servo goes on holding p_r; otherwise the plate, away from the layer, stops.
      if (spec.servo_release)
        state_.ramp_from = state_.ramp_to = spec.lift_speed;  // the lift's ramp is over: the servo alone
      else
        set_plate_velocity(sim, 0.0);
      sim.settings().drag_rate = spec.rest_drag_rate;
      state_.relax_start_time = sim.time();
      break;
    case Phase::done:
      state_.released = reading(sim);
      sim.settings().drag_rate = 0.0;
      sim.set_wall_velocity(kTopWall, 0.0);
      state_.ramp_from = state_.ramp_to = 0.0;
      // The released thickness: under the servo's residual pressure, the plate gap; after a
      // relaxation away from the layer, the top of the layer's surface; without one, the plate gap
      // when it lost contact.
      state_.final_gap = !spec.servo_release && state_.relax_start_time > 0.0
                             ? layer_top(sim.particles()) - sim.walls()[kBottomWall].position
                             : sim.gap();
      state_.final_porosity = sim.porosity();
      state_.done_step = sim.step_count();
      break;
    case Phase::settle: break;
  }
  state_.phase = phase;
}

std::optional<Phase> LoadingProtocol::after_step(Simulation& sim) {
  const CalenderingSpec& spec = calendering_;
  const double pressure = sim.wall_pressure(kTopWall);
  apply_ramp(sim);  // the plate's velocity for the next step
  if (state_.phase != Phase::settle && pressure > state_.max_pressure) {
    state_.max_pressure = pressure;
    state_.gap_at_max_pressure = sim.gap();
  }
  switch (state_.phase) {
    case Phase::settle: {
      // Settled: past the shortest time and slow enough (checked every 50 steps), or out of time.
      const double max_time = settle_.max_time > 0.0 ? settle_.max_time : 3.0 * settle_.time;
      if (sim.time() < state_.phase_end_time || sim.step_count() % 50 != 0) break;
      const double rms_speed = std::sqrt(2.0 * sim.kinetic_energy() / total_mass_);
      if (rms_speed < settle_.speed_tolerance || sim.time() >= max_time) return Phase::load;
      break;
    }
    case Phase::load: {
      if (state_.approaching) {
        const double dt = sim.settings().dt;
        const double window = spec.approach_window;
        state_.approach_average =
            window > 0.0 ? state_.approach_average + (pressure - state_.approach_average) * std::min(1.0, dt / window)
                         : pressure;
        const double solid_fraction = solid_volume_ / (box_.lx * box_.ly * sim.gap());
        const bool ended = spec.approach_solid_fraction ? solid_fraction >= *spec.approach_solid_fraction
                                                        : state_.approach_average >= spec.approach_pressure;
        if (ended) {
          state_.approaching = false;
          state_.press_start_gap = sim.gap();
          set_plate_velocity(sim, -spec.speed);
        }
      }
      // Particles whose centres are above the plate were passed through, not pressed: the plate
      // moved too far per step (and its pressure, or the target, means nothing then).
      if (const std::size_t above = particles_above_plate(sim); above > 0)
        throw ProtocolError("the top plate passed through " + std::to_string(above) +
                            " particles (their centres are above it) instead of pressing them: it moves " +
                            format_number(std::abs(sim.walls()[kTopWall].velocity) * sim.settings().dt) +
                            " µm per step, too far for contact forces to stop the particles; lower "
                            "calendering.speed (" +
                            format_number(spec.speed) + " µm/µs) or approach_speed (" +
                            format_number(spec.approach_speed) + " µm/µs), or time.dt");
      const bool thick_reached = spec.target_thickness && sim.gap() <= *spec.target_thickness;
      const bool pressure_reached = spec.target_pressure && pressure >= *spec.target_pressure;
      if (thick_reached || pressure_reached) return Phase::hold;
      if (sim.gap() * box_.lx * box_.ly <= solid_volume_) {
        throw ProtocolError("calendering.target_pressure = " + format_number(spec.target_pressure.value_or(0.0)) +
                            " MPa cannot be reached: the top plate reached the thickness of the solid (" +
                            format_number(sim.gap()) + " µm) at " + format_number(pressure) +
                            " MPa; lower the target or give target_thickness");
      }
      break;
    }
    case Phase::hold: {
      if (spec.servo_hold && spec.target_pressure) {
        const engine::PlateServo servo_law{*spec.target_pressure, *spec.target_pressure, spec.speed, spec.servo_gain,
                                           spec.servo_tolerance};
        sim.set_wall_velocity(kTopWall, -plate_servo_speed(sim, servo_law, pressure));
      }
      if (sim.time() < state_.phase_end_time) break;
      const double ratio = sim.unbalanced_force_ratio();
      if (ratio < spec.equilibrium_ratio) return Phase::unload;
      const double limit = spec.hold_time_limit();
      if (sim.time() - state_.hold_start_time >= limit)
        throw ProtocolError("the loaded state did not reach equilibrium: after a hold of " +
                            format_number(sim.time() - state_.hold_start_time) +
                            " µs (calendering.max_hold_time) the unbalanced-force ratio is " + format_number(ratio) +
                            ", above calendering.equilibrium_ratio = " + format_number(spec.equilibrium_ratio) +
                            "; hold longer, damp more, or load more slowly");
      break;
    }
    case Phase::unload:
      if (spec.servo_release) {
        if (!(state_.loaded.pressure > 0.0))
          throw ProtocolError(
              "calendering.release = \"servo\" needs a pressure to unload from: the top plate carried " +
              format_number(state_.loaded.pressure) + " MPa at the end of the hold; use release = \"contact_lost\"");
        // Down to p_r (from above; the first time the pressure is within the tolerance or below).
        if (servo_release_step(sim, pressure) || pressure < release_pressure()) return Phase::relax;
        break;
      }
      if (sim.wall_contact_count(kTopWall) == 0 || pressure <= spec.release_fraction * state_.max_pressure)
        return spec.relax_time > 0.0 ? Phase::relax : Phase::done;
      break;
    case Phase::relax: {
      // Under the servo, the released state is read with the plate standing still at p_r.
      const bool at_rest_pressure = !spec.servo_release || servo_release_step(sim, pressure);
      if (sim.time() - state_.relax_start_time < spec.relax_time) break;
      const double ratio = sim.unbalanced_force_ratio();
      if (ratio < spec.equilibrium_ratio && at_rest_pressure) return Phase::done;
      const double limit = spec.relax_time_limit();
      if (sim.time() - state_.relax_start_time >= limit)
        throw ProtocolError("the released state did not reach equilibrium: after " +
                            format_number(sim.time() - state_.relax_start_time) +
                            " µs of relaxation (calendering.max_relax_time) the unbalanced-force ratio is " +
                            format_number(ratio) +
                            ", above calendering.equilibrium_ratio = " + format_number(spec.equilibrium_ratio) +
                            (at_rest_pressure ? std::string()
                                              : "; the plate pressure " + format_number(pressure) +
                                                    " MPa is not within calendering.release_tolerance of p_r = " +
                                                    format_number(release_pressure()) + " MPa"));
      break;
    }
    case Phase::done: break;
  }
  return std::nullopt;
}

double LoadingProtocol::progress(const Simulation& sim) const noexcept {
  if (done()) return 1.0;
  const CalenderingSpec& spec = calendering_;
  const double settle = state_.phase == Phase::settle ? std::max(settle_.time, sim.time()) : state_.load_start_time;
  // Expected load travel: to the target thickness, or for a pressure target to about random close
  // packing (64 % solid).
  const double start_gap = state_.phase == Phase::settle ? std::max(sim.highest_point(), 1e-9) : state_.load_start_gap;
  const double packed_gap = solid_volume_ / (0.64 * box_.lx * box_.ly);
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
    case Phase::hold:
      elapsed = settle + load + std::clamp(hold - (state_.phase_end_time - sim.time()), 0.0, hold);
      break;
    case Phase::unload:
      elapsed = settle + load + hold + std::clamp((sim.gap() - state_.min_gap) / spec.lift_speed, 0.0, 0.95 * unload);
      break;
    case Phase::relax: elapsed = 0.97 * total; break;
    case Phase::done: return 1.0;
  }
  return std::clamp(elapsed / total, 0.0, 0.999);
}

}  // namespace ellc::scenario
