// `ellc export-lammps SCENARIO.toml -o DIR [--seed N] [--name NAME]`
// One study, two engines: writes the scenario's generated packing (the one `ellc dem` starts
// from, same seed) as a LAMMPS data file, DIR/packing.data, and an input script, DIR/in.scenario,
// with the same material, contact sub-models, walls (fix wall/ellipsoid/bk) and loading protocol,
// for `lmp_ellc -in in.scenario` (run in DIR). The LAMMPS run writes DIR/timeseries.csv with the
// built-in engine's column names for the quantities both compute. docs/lammps.md lists what the
// script cannot express. The hold and relax stages end on the engine's equilibrium criterion
// (the unbalanced-force ratio, fix wall/ellipsoid/bk's element 9); drag is LAMMPS's fix langevin
// at zero temperature, which is the engine's −γ m v.
//
// Units: the scenario's µm, µs, ng, µN, MPa become LAMMPS `units micro` (µm, µs, pg, nN, kPa):
// masses, forces and pressures × 10³.

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "command_registry.hpp"
#include "ellc/engine/time_step.hpp"
#include "ellc/geometry/ellipsoid.hpp"
#include "ellc/io/input_error.hpp"
#include "ellc/scenario/packing.hpp"
#include "ellc/scenario/scenario.hpp"

namespace ellc::cli {
namespace {

constexpr double kPerMilli = 1e3;  // ng → pg, µN → nN, MPa → kPa

struct ExportOptions {
  std::string scenario_path;
  std::string output_directory;
  long long seed = -1;
  std::string name = "scenario";       // in.NAME; the data file is packing.data, or NAME.data for another name
  std::vector<std::string> overrides;  // --set KEY=VALUE, as for ellc dem
};

std::string number(double value) { return format_number(value); }

// What the LAMMPS input calls the plate's position over a half-cosine ramp of its velocity from
// v0 to v1 over `ramp` µs, starting at time ts from z0 (the engine's LoadingProtocol::apply_ramp,
// integrated): z = z0 + v0 τ + (v1 − v0) [s/2 − ramp/(2π) sin(π s/ramp) + (τ − s)], s = min(τ, ramp).
std::string ramp_expression(double v0, double v1, double ramp) {
  const std::string tau = "(time-v_ts)";
  if (ramp <= 0.0 || v0 == v1) return "v_zs+(" + number(v1) + ")*" + tau;
  // min(τ, ramp) with LAMMPS's comparison operators (its min() is a reduction over a vector).
  const std::string s =
      "((" + tau + "<" + number(ramp) + ")*" + tau + "+(" + tau + ">=" + number(ramp) + ")*" + number(ramp) + ")";
  return "v_zs+(" + number(v0) + ")*" + tau + "+(" + number(v1 - v0) + ")*(" + s + "/2-" + number(ramp / (2.0 * M_PI)) +
         "*sin(PI*" + s + "/" + number(ramp) + ")+" + tau + "-" + s + ")";
}

void write_data_file(const std::string& path, const scenario::Scenario& scenario, const engine::ParticleSet& particles,
                     double zlo, double zhi) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path);
  out.precision(17);
  out << "LAMMPS data file: the packing of " << std::filesystem::path(scenario.path).filename().string() << " (seed "
      << scenario.packing.seed << "), written by ellc export-lammps; units micro\n\n";
  // Several species ([[species]]): atom type k + 1 is species k, with its own density.
  const std::vector<scenario::SpeciesSpec> species = scenario::species_of(scenario.packing);
  out << particles.size() << " atoms\n" << species.size() << " atom types\n" << particles.size() << " ellipsoids\n\n";
  out << "0 " << scenario.box.lx << " xlo xhi\n0 " << scenario.box.ly << " ylo yhi\n"
      << zlo << ' ' << zhi << " zlo zhi\n\n";
  // atom-ID atom-type ellipsoidflag density x y z (density in pg/µm³, after mass scaling)
  out << "Atoms # ellipsoid\n\n";
  for (std::size_t k = 0; k < particles.size(); ++k) {
    const Eigen::Vector3d& x = particles.position[k];
    const std::uint16_t kind = particles.species[k];
    out << particles.id[k] + 1 << ' ' << kind + 1 << " 1 " << species[kind].density * kPerMilli << ' ' << x.x() << ' '
        << x.y() << ' ' << x.z() << '\n';
  }
  // atom-ID shapex shapey shapez quatw quati quatj quatk (shape: diameters; quaternion body → world)
  out << "\nEllipsoids\n\n";
  for (std::size_t k = 0; k < particles.size(); ++k) {
    const Eigen::Vector3d& a = particles.semi_axes[k];
    const Eigen::Quaterniond& q = particles.orientation[k];
    out << particles.id[k] + 1 << ' ' << 2.0 * a.x() << ' ' << 2.0 * a.y() << ' ' << 2.0 * a.z() << ' ' << q.w() << ' '
        << q.x() << ' ' << q.y() << ' ' << q.z() << '\n';
  }
}

// One line per species (pair_coeff k k, its material): the pair style mixes two types by the
// same make_interaction as the built-in engine (eq. 3, Y = min), with the one [model] of the scenario.
std::string pair_coeff_lines(const scenario::Scenario& scenario) {
  const std::vector<Material> materials = engine::species_materials(scenario.contact);
  const ContactModel& model = scenario.contact.model;
  const auto& fit = model.law.fit;
  std::ostringstream line;
  for (std::size_t k = 0; k < materials.size(); ++k) {
    const Material& m = materials[k];
    const std::string type = std::to_string(k + 1);
    line << "pair_coeff   " << type << ' ' << type << ' ' << number(m.youngs_modulus * kPerMilli) << ' '
         << number(m.poisson_ratio) << ' ' << number(m.yield_stress * kPerMilli) << " &\n  normal "
         << name_of(model.normal) << " damping_model " << name_of(model.damping) << " normal_damping "
         << number(model.normal_damping) << " tangential_damping " << number(model.tangential_damping)
         << " &\n  tangential_model " << name_of(model.tangential) << " tangential_stiffness "
         << number(model.tangential_stiffness_ratio) << " friction " << number(model.friction)
         << " narrow_phase_final_step " << number(model.narrow_phase_final_step) << " &\n  lambda "
         << number(fit.lambda_amplitude) << ' ' << number(fit.lambda_rate) << ' ' << number(fit.lambda_offset)
         << " epsilon " << number(fit.epsilon_amplitude) << ' ' << number(fit.epsilon_rate) << ' '
         << number(fit.epsilon_offset) << " exponent " << number(fit.transition_exponent) << " yield_factor "
         << number(model.law.yield_pressure_factor) << '\n';
  }
  return line.str();
}

std::string wall_material(const scenario::Scenario& scenario) {
  const auto& wall = scenario.contact.wall_material;
  if (!wall) return "material particle";
  if (std::isinf(wall->youngs_modulus)) return "rigid";
  return "material " + number(wall->youngs_modulus * kPerMilli) + " " + number(wall->poisson_ratio) + " " +
         (std::isinf(wall->yield_stress) ? std::string("inf") : number(wall->yield_stress * kPerMilli));
}

// Drag −γ m v on every particle: fix langevin at zero temperature is exactly that (damp = 1/γ).
std::string drag_fix(double rate) {
  if (rate <= 0.0) return "unfix drag\nfix drag all viscous 0.0\n";
  return "unfix drag\nfix drag all langevin 0.0 0.0 " + number(1.0 / rate) + " 20261202\n";
}

void write_input(const std::string& path, const std::string& data_name, const scenario::Scenario& scenario,
                 const engine::ParticleSet& particles, double dt, double plate_start, double layer_top) {
  const scenario::CalenderingSpec& c = scenario.calendering;
  const scenario::SettleSpec& settle = scenario.settle;
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path);
  const double area = scenario.box.lx * scenario.box.ly;
  const double solid = particles.total_volume();
  const long every = std::max(1L, scenario.output.csv_every);
  // A stage ends on its condition (fix halt); its step budget only guards against a run that
  // never gets there: ten times the expected travel time.
  const auto budget = [&](double time) {
    return std::to_string(static_cast<long long>(std::ceil(10.0 * time / dt)) + 1000);
  };
  const double travel = std::max(plate_start - solid / (0.64 * area), 1.0);

  out << "# " << std::filesystem::path(scenario.path).filename().string()
      << " for LAMMPS: written by `ellc export-lammps` (docs/lammps.md).\n";
  if (scenario.source != scenario.path) out << "# With the overrides of: " << scenario.source << "\n";
  out << "# Run in this directory:  lmp_ellc -in " << std::filesystem::path(path).filename().string()
      << "   (or mpirun -np N lmp_ellc -in ...)\n"
      << "# Units micro: µm, µs, pg, nN, kPa (the scenario's masses, forces and pressures x 1e3).\n"
      << "# Writes timeseries.csv with the built-in engine's column names.\n\n"
      << "units        micro\natom_style   ellipsoid\nboundary     p p f\nprocessors   * * 1\n"
      << "read_data    " << data_name << "\n\n";
  out << "pair_style   ellipsoid/bk hertz " << (scenario.contact.model.hertz == HertzMode::exact ? "exact" : "hale")
      << '\n'
      << pair_coeff_lines(scenario);
  out << "timestep     " << number(dt) << "   # µs: " << number(scenario.time_step_safety)
      << " x Rayleigh time of the smallest semi-axis, as ellc dem\n";
  out << "neighbor     " << number(scenario.skin > 0.0 ? scenario.skin : 0.2 * scenario.packing.mean_radius)
      << " bin\nneigh_modify every 1 delay 0 check yes\n\n";

  out << "# The floor at z = 0 and the plate; the plate follows v_ztop (redefined per stage) or the servo.\n"
      << "variable     ts equal 0.0\nvariable     zs equal " << number(plate_start) << '\n'
      << "variable     ztop equal v_zs\n"
      << "fix          wall all wall/ellipsoid/bk zplane 0.0 v_ztop " << wall_material(scenario) << " friction "
      << number(scenario.contact.wall_friction) << '\n'
      << "fix          integrate all nve/asphere\nfix          drag all viscous 0.0\n"
      << "compute      contacts all ellipsoid/bk/contacts\n\n";

  out << "# The built-in engine's columns (MPa, µm): timeseries.csv\n"
      << "variable     phase string settle\n"
      << "variable     plate_position equal f_wall[8]\n"
      << "variable     thickness equal f_wall[8]-f_wall[7]\n"
      << "variable     plate_pressure equal f_wall[6]/" << number(area * kPerMilli) << '\n'
      << "variable     bottom_pressure equal -f_wall[3]/" << number(area * kPerMilli) << '\n'
      << "variable     porosity equal 1-" << number(solid) << "/(" << number(area) << "*v_thickness)\n"
      << "variable     coordination_number equal 2*c_contacts/count(all)\n"
      << "variable     unbalanced_force_ratio equal f_wall[9]\n"
      << "fix          series all print " << every
      << " \"${step},${time},${phase},${plate_position},${thickness},${plate_pressure},${bottom_pressure},"
         "${porosity},${coordination_number},${unbalanced_force_ratio}\" file timeseries.csv screen no title "
         "\"step,time,phase,plate_position,thickness,plate_pressure,bottom_pressure,porosity,coordination_number,"
         "unbalanced_force_ratio\"\n"
      << "variable     step equal step\nvariable     time equal time\n"
      << "thermo_style custom step time v_plate_position v_plate_pressure v_porosity v_coordination_number\n"
      << "thermo       " << every * 50 << "\n\n";

  if (settle.time > 0.0) {
    const double mass = [&] {
      double total = 0.0;
      for (double m : particles.mass) total += m;
      return total * kPerMilli;
    }();
    out << "# settle: gravity and drag, at least settle.time, then until the rms speed is below the tolerance\n"
        << "fix          gravity all gravity " << number(settle.gravity) << " vector 0 0 -1\n"
        << drag_fix(settle.drag_rate) << "run          " << static_cast<long long>(std::ceil(settle.time / dt)) << '\n'
        << "variable     settled equal sqrt(2*ke/" << number(mass) << ")<" << number(settle.speed_tolerance) << '\n'
        << "fix          halt all halt 50 v_settled > 0.5 error continue\n"
        << "run          " << static_cast<long long>(std::ceil(std::max(settle.max_time - settle.time, 0.0) / dt))
        << "\nunfix        halt\nunfix        gravity\n\n";
  }
  out << "# load: the plate starts start_gap above the layer, approaches, then calenders\n"
      << "variable     phase string load\n"
      << drag_fix(0.0);
  if (c.gravity > 0.0) out << "fix          gravity all gravity " << number(c.gravity) << " vector 0 0 -1\n";
  // Settled: the plate restarts start_gap above the highest centre plus the largest semi-axis (the
  // engine takes the highest surface point, which LAMMPS does not report).
  double largest = 0.0;
  for (double r : particles.bounding_radius) largest = std::max(largest, r);
  out << "variable     ts equal $(time:%.17g)\n"
      << "variable     zs equal "
      << (settle.time > 0.0 ? "$(bound(all,zmax)+" + number(largest + c.start_gap) + ":%.17g)"
                            : number(layer_top + c.start_gap))
      << '\n';
  const bool approach = c.approach_speed > 0.0 && c.approach_speed != c.speed;
  const double first_speed = c.approach_speed > 0.0 ? c.approach_speed : c.speed;
  out << "variable     ztop equal " << ramp_expression(0.0, -first_speed, c.ramp_time) << '\n';
  std::string target;
  if (c.target_pressure) target = "v_plate_pressure>=" + number(*c.target_pressure);
  if (c.target_thickness)
    target = (target.empty() ? "" : target + "||") + "v_thickness<=" + number(*c.target_thickness);
  if (approach) {
    const std::string ended = c.approach_solid_fraction ? "(1-v_porosity)>=" + number(*c.approach_solid_fraction)
                                                        : "v_plate_pressure>=" + number(c.approach_pressure);
    out << "variable     approached equal (" << ended << ")||(" << target << ")\n"
        << "fix          halt all halt 1 v_approached > 0.5 error continue\n"
        << "run          " << budget(travel / first_speed) << "\nunfix        halt\n"
        << "variable     ts equal $(time:%.17g)\nvariable     zs equal $(v_plate_position:%.17g)\n"
        << "variable     ztop equal " << ramp_expression(-first_speed, -c.speed, c.ramp_time) << '\n';
  }
  out << "variable     loaded equal " << target << '\n'
      << "fix          halt all halt 1 v_loaded > 0.5 error continue\n"
      << "run          " << budget(travel / c.speed)
      << "\nunfix        halt\n"
      // The step that met the target falls between output rows in general: say it here.
      << "print        \"ellc: load ended at $(v_plate_pressure:%.17g) MPa, thickness $(v_thickness:%.17g) um\"\n\n";

  // The engine's equilibrium criterion (LoadingProtocol::after_step): at least the stage's time,
  // then until the unbalanced-force ratio (f_wall[9], the engine's definition) is below
  // equilibrium_ratio, checked every step; out of time (the engine's limit), the run stops with
  // the engine's message.
  const std::string ratio = number(c.equilibrium_ratio);
  const auto out_of_time = [&](const std::string& ended, const std::string& start, const std::string& what,
                               const std::string& limit, const std::string& advice) {
    out << "if           \"${" << ended << "} < 0.5\" then &\n  \"print 'ERROR: ellc export-lammps: " << what
        << " did not reach equilibrium: after $(time-v_" << start << ":%.6g) us (calendering." << limit
        << ") the unbalanced-force ratio is $(v_unbalanced_force_ratio:%.6g)'\" &\n"
        << "  \"print '  above calendering.equilibrium_ratio = " << ratio << advice << "'\" \"quit 1\"\n";
  };
  const auto steps = [&](double time) { return std::to_string(static_cast<long long>(std::ceil(time / dt))); };

  const double hold_limit = c.hold_time_limit();
  out << "# hold: " << (c.servo_hold ? "the servo holds the target pressure" : "the plate stops")
      << " with rest_drag_rate, at least hold_time, then until\n# the unbalanced-force ratio is below "
         "equilibrium_ratio (max_hold_time)\nvariable     phase string hold\n"
      << drag_fix(c.rest_drag_rate)
      << "variable     ts equal $(time:%.17g)\nvariable     zs equal $(v_plate_position:%.17g)\n";
  if (c.servo_hold && c.target_pressure)
    out << "fix_modify   wall servo hi " << number(*c.target_pressure * kPerMilli) << ' ' << number(c.speed)
        << " servo_gain " << number(c.servo_gain) << " servo_tolerance " << number(c.servo_tolerance) << '\n';
  else
    out << "variable     ztop equal " << ramp_expression(-c.speed, 0.0, c.ramp_time) << '\n';
  out << "variable     hold_start equal $(time:%.17g)\n"
      << "variable     held equal (time>=v_hold_start+" << number(c.hold_time) << ")&&(v_unbalanced_force_ratio<"
      << ratio << ")\nfix          halt all halt 1 v_held > 0.5 error continue\n"
      << "run          " << steps(hold_limit) << "\nunfix        halt\n";
  out_of_time("held", "hold_start", "the loaded state", "max_hold_time",
              "; hold longer, damp more, or load more slowly");
  out << "print        \"ellc: hold ended after $(time-v_hold_start:%.17g) us, unbalanced-force ratio "
         "$(v_unbalanced_force_ratio:%.17g)\"\n\n";

  const bool relax = c.relaxes();
  out << "# unload: "
      << (c.servo_release ? "the servo lowers the plate pressure to p_r = release_pressure_fraction x the held pressure"
                          : "the plate lifts until it loses contact (pressure below release_fraction of the hold's)")
      << "\nvariable     phase string unload\n"
      << drag_fix(0.0) << "variable     ts equal $(time:%.17g)\nvariable     zs equal $(v_plate_position:%.17g)\n";
  const std::string unload_steps = budget(0.3 * travel / c.lift_speed);
  if (c.servo_release) {
    // The engine's release servo, lift_speed · clamp(g (p − p_r)/p_held, −1, 1) upwards, is the
    // wall fix's servo at p_r with the gain g · p_r/p_held = g · release_pressure_fraction. The
    // engine caps it by the lift's ramp: the plate follows the ramp until the servo asks for less.
    out << "variable     held_pressure equal $(v_plate_pressure:%.17g)\n"
        << "if           \"${held_pressure} <= 0\" then &\n"
        << "  \"print 'ERROR: ellc export-lammps: calendering.release = servo needs a pressure to unload from: the "
           "top plate carried ${held_pressure} MPa at the end of the hold'\" \"quit 1\"\n"
        << "variable     release_pressure equal " << number(c.release_pressure_fraction) << "*v_held_pressure\n"
        << "variable     released equal v_plate_pressure<=" << number(1.0 + c.release_tolerance)
        << "*v_release_pressure\n";
    if (c.ramp_time > 0.0) {
      const std::string s = "(((time-v_ts)<" + number(c.ramp_time) +
                            ")*(time-v_ts)+((time-v_ts)>=" + number(c.ramp_time) + ")*" + number(c.ramp_time) + ")";
      if (c.servo_hold && c.target_pressure) out << "fix_modify   wall servo off\n";
      out << "variable     ztop equal " << ramp_expression(0.0, c.lift_speed, c.ramp_time) << '\n'
          << "variable     ramp_speed equal " << number(0.5 * c.lift_speed) << "*(1-cos(PI*" << s << "/"
          << number(c.ramp_time) << "))\n"
          << "variable     servo_below_ramp equal " << number(c.lift_speed * c.servo_gain)
          << "*(v_plate_pressure-v_release_pressure)/v_held_pressure<v_ramp_speed\n"
          << "variable     servo_takes_over equal v_released||v_servo_below_ramp\n"
          << "fix          halt all halt 1 v_servo_takes_over > 0.5 error continue\n"
          << "run          " << steps(c.ramp_time) << "\nunfix        halt\n";
    }
    out << "fix_modify   wall servo hi $(" << number(kPerMilli) << "*v_release_pressure:%.17g) " << number(c.lift_speed)
        << " servo_gain " << number(c.servo_gain * c.release_pressure_fraction) << " servo_tolerance "
        << number(c.release_tolerance) << '\n'
        << "if           \"${released} < 0.5\" then &\n"
        << "  \"fix          halt all halt 1 v_released > 0.5 error continue\" &\n"
        << "  \"run          " << unload_steps << "\" \"unfix        halt\"\n";
  } else {
    out << "variable     released equal v_plate_pressure<=" << number(c.release_fraction)
        << "*$(v_plate_pressure:%.17g)\n";
    if (c.servo_hold && c.target_pressure) out << "fix_modify   wall servo off\n";
    out << "variable     ztop equal " << ramp_expression(0.0, c.lift_speed, c.ramp_time) << '\n'
        << "fix          halt all halt 1 v_released > 0.5 error continue\n"
        << "run          " << unload_steps << "\nunfix        halt\n";
  }
  if (relax) {
    const double relax_limit = c.relax_time_limit();
    out << "\n# relax: " << (c.servo_release ? "the servo holds p_r" : "plate at rest")
        << ", rest_drag_rate, at least relax_time, then until the unbalanced-force ratio\n# is below "
           "equilibrium_ratio"
        << (c.servo_release ? " and the plate pressure within release_tolerance of p_r" : "")
        << " (max_relax_time)\nvariable     phase string relax\n"
        << drag_fix(c.rest_drag_rate) << "variable     relax_start equal $(time:%.17g)\n";
    if (!c.servo_release)
      out << "variable     ts equal $(time:%.17g)\nvariable     zs equal $(v_plate_position:%.17g)\n"
          << "variable     ztop equal " << ramp_expression(c.lift_speed, 0.0, c.ramp_time) << '\n';
    out << "variable     relaxed equal (time>=v_relax_start+" << number(c.relax_time) << ")&&(v_unbalanced_force_ratio<"
        << ratio << ")";
    if (c.servo_release)
      out << "&&(abs(v_plate_pressure-v_release_pressure)<=" << number(c.release_tolerance) << "*v_release_pressure)";
    out << "\nfix          halt all halt 1 v_relaxed > 0.5 error continue\n"
        << "run          " << steps(relax_limit) << "\nunfix        halt\n";
    out_of_time("relaxed", "relax_start",
                c.servo_release ? "the released state (the ratio, and the plate pressure within "
                                  "calendering.release_tolerance of p_r = $(v_release_pressure:%.6g) MPa)"
                                : "the released state",
                "max_relax_time", "");
    out << "print        \"ellc: relax ended after $(time-v_relax_start:%.17g) us, unbalanced-force ratio "
           "$(v_unbalanced_force_ratio:%.17g)\"\n";
    if (c.servo_release) out << "fix_modify   wall servo off\n";
  }
  out << "variable     phase string done\nrun          0\n";
}

void run_export(const ExportOptions& options) {
  scenario::Scenario scenario = scenario::read_scenario(options.scenario_path, options.overrides);
  if (options.seed >= 0) scenario.packing.seed = static_cast<std::uint64_t>(options.seed);
  for (const auto& warning : scenario.warnings) std::fprintf(stderr, "ellc: warning: %s\n", warning.c_str());
  const scenario::PackingSpec& spec = scenario.packing;
  // The packing `ellc dem` builds (ScenarioRunner::build_packing): same generator, seed and test.
  const engine::ParticleSet particles = scenario::generate_packing(
      spec, scenario.box, 0.0, spec.spheres ? scenario::OverlapTest{} : scenario::ellipsoid_overlap_test());
  const double dt = scenario.dt.value_or(scenario::packing_time_step(particles, scenario));
  double top = 0.0;        // highest bounding sphere (where the engine puts the plate to settle)
  double layer_top = 0.0;  // highest surface point (where the load starts without settling)
  for (std::size_t k = 0; k < particles.size(); ++k) {
    top = std::max(top, particles.position[k].z() + particles.bounding_radius[k]);
    layer_top =
        std::max(layer_top, Ellipsoid(particles.semi_axes[k], Pose{particles.position[k], particles.orientation[k]})
                                .axis_aligned_bounds()
                                .upper.z());
  }
  const double plate_start = top + 2.0 * spec.mean_radius;
  namespace fs = std::filesystem;
  fs::create_directories(options.output_directory);
  const double margin = 4.0 * spec.mean_radius;
  const std::string data_name = options.name == "scenario" ? "packing.data" : options.name + ".data";
  const fs::path directory(options.output_directory);
  write_data_file((directory / data_name).string(), scenario, particles, -margin,
                  std::max(plate_start, layer_top + scenario.calendering.start_gap) + margin);
  write_input((directory / ("in." + options.name)).string(), data_name, scenario, particles, dt, plate_start,
              layer_top);
  std::printf("ellc export-lammps: %zu particles, dt = %s µs -> %s, %s\n", particles.size(), number(dt).c_str(),
              (directory / data_name).string().c_str(), (directory / ("in." + options.name)).string().c_str());
}

const RegisterCommand registration([](CLI::App& root) {
  auto options = std::make_shared<ExportOptions>();
  CLI::App* command = root.add_subcommand(
      "export-lammps", "Write a scenario's packing and protocol as a LAMMPS data file and input script (lmp_ellc)");
  command->add_option("scenario", options->scenario_path, "Scenario file (TOML), e.g. examples/calendering.toml")
      ->required();
  command->add_option("-o,--output", options->output_directory, "Directory for packing.data and in.scenario")
      ->required();
  command->add_option("--seed", options->seed, "Packing seed (default: the scenario's [packing] seed)");
  command->add_option("--name", options->name, "Write in.NAME and NAME.data (default: in.scenario, packing.data)");
  add_scenario_overrides(*command, options->overrides);
  command->callback([options] { run_export(*options); });
});

}  // namespace
}  // namespace ellc::cli
