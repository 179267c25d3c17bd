#include "ellc/scenario/state_analysis.hpp"

#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "ellc/geometry/ellipsoid.hpp"
#include "ellc/io/input_error.hpp"
#include "ellc/io/toml_text.hpp"
#include "ellc/scenario/checkpoint.hpp"

namespace ellc::scenario {

microstructure::Packing packing_of(const engine::Simulation& simulation) {
  const engine::ParticleSet& particles = simulation.particles();
  microstructure::Packing packing;
  packing.centres = particles.position;
  packing.semi_axes = particles.semi_axes;
  packing.orientations = particles.orientation;
  const auto& box = simulation.settings().box;
  packing.box.lower = {0.0, 0.0, simulation.walls()[engine::kBottomWall].position};
  packing.box.upper = {box.lx, box.ly, simulation.walls()[engine::kTopWall].position};
  packing.box.periodic = {true, true, false};
  simulation.for_each_contact([&](const engine::ContactView& view) {
    if (view.wall >= 0) return;
    const Ellipsoid body_i(particles.semi_axes[view.i], Pose{view.centre_i, particles.orientation[view.i]});
    const Ellipsoid body_j(particles.semi_axes[view.j], Pose{view.other, particles.orientation[view.j]});
    microstructure::ContactRecord record;
    record.i = view.i;
    record.j = view.j;
    record.point = 0.5 * (body_i.support_point(view.normal) + body_j.support_point(-view.normal));
    record.centre_j = view.other;
    record.normal_force = view.normal_force;
    record.max_overlap = view.max_overlap;
    record.regime = static_cast<int>(view.regime);
    packing.contacts.push_back(record);
  });
  return packing;
}

microstructure::Packing read_checkpoint_packing(const std::string& checkpoint_path, const std::string& scenario_path) {
  const Scenario scenario = read_scenario(scenario_path);
  engine::EngineSettings settings;
  settings.contact = scenario.contact;
  settings.box = scenario.box;
  settings.skin = scenario.skin;
  settings.max_speed = scenario.max_speed;
  Checkpoint checkpoint = read_checkpoint(checkpoint_path, scenario, settings);
  engine::Simulation& simulation = *checkpoint.simulation;
  // The checkpoint holds the state, not the forces of its last evaluation: evaluate them once at
  // the stored positions (a step of zero length, no gravity, no drag, walls at rest).
  simulation.settings().dt = 0.0;
  simulation.settings().gravity.setZero();
  simulation.settings().drag_rate = 0.0;
  simulation.set_wall_velocity(engine::kBottomWall, 0.0);
  simulation.set_wall_velocity(engine::kTopWall, 0.0);
  simulation.step();
  return packing_of(simulation);
}

microstructure::AnalysisOptions analysis_options(const Scenario& scenario) {
  microstructure::AnalysisOptions options;
  if (!scenario.analysis) return options;
  const AnalysisSpec& spec = *scenario.analysis;
  options.resolution.voxels_per_semi_axis = spec.voxels_per_semi_axis;
  options.resolution.spacing = spec.spacing;
  options.resolution.memory_limit_bytes = spec.memory_limit_gib * 1024.0 * 1024.0 * 1024.0;
  options.coarse_factor = spec.coarse_factor;
  for (std::size_t axis = 0; axis < 3; ++axis)
    options.tortuosity_axes[axis] = spec.axes.find("xyz"[axis]) != std::string::npos;
  return options;
}

std::string states_summary(const std::vector<StateAnalysis>& states) {
  std::ostringstream out;
  std::vector<double> porosity;
  std::vector<double> tortuosity;
  std::vector<double> tortuosity_extrapolated;  // the same states' lines to zero voxel size
  bool every_state_extrapolated = true;
  for (const StateAnalysis& state : states) {
    const auto& report = state.report;
    out << "analysis_" << state.state << "_porosity = " << toml_float(report.porosity_voxels) << '\n';
    if (const auto& tau = report.tortuosity[2]) {
      out << "analysis_" << state.state << "_tortuosity_z = " << toml_float(tau->tortuosity) << '\n';
      if (!tau->reason.empty())
        out << "analysis_" << state.state << "_tortuosity_z_note = " << toml_string(tau->reason) << '\n';
      porosity.push_back(report.porosity_voxels);
      tortuosity.push_back(tau->tortuosity);
      const auto& line = report.tortuosity_extrapolated[2].tortuosity;
      every_state_extrapolated = every_state_extrapolated && line.has_value();
      tortuosity_extrapolated.push_back(line.value_or(std::numeric_limits<double>::quiet_NaN()));
    }
    const std::string at_coarse =
        "  # at " + format_number(report.coarse_spacing) + " um voxels (" + format_number(report.spacing) + " above)\n";
    if (const auto& coarse = report.tortuosity_coarse[2])
      out << "analysis_" << state.state << "_tortuosity_z_coarse = " << toml_float(coarse->tortuosity) << at_coarse;
    if (const auto& estimate = report.tortuosity_extrapolated[2].tortuosity)
      out << "analysis_" << state.state << "_tortuosity_z_extrapolated = " << toml_float(*estimate)
          << "  # to zero voxel size from the two above (first order)\n";
    else if (!report.tortuosity_extrapolated[2].reason.empty())
      out << "analysis_" << state.state
          << "_tortuosity_z_extrapolated_note = " << toml_string(report.tortuosity_extrapolated[2].reason) << '\n';
    out << "analysis_" << state.state << "_pore_radius_median_um = " << toml_float(report.pore_sizes.median_radius)
        << '\n';
    if (const auto& coarse = report.pore_sizes_coarse)
      out << "analysis_" << state.state << "_pore_radius_median_um_coarse = " << toml_float(coarse->median_radius)
          << at_coarse;
  }
  const double alpha = microstructure::fit_bruggeman_exponent(porosity, tortuosity);
  if (std::isfinite(alpha))
    out << "analysis_bruggeman_exponent = " << toml_float(alpha)
        << "  # D_eff/D = porosity^alpha over the states above (Bruggeman: 1.5)\n";
  else
    out << "analysis_bruggeman_exponent = nan  # no state with a finite tortuosity and 0 < porosity < 1\n";
  // The same fit on the lines: each state's τ lies between its line and τ(h), so α between the two
  // exponents (α grows with τ at a fixed ε < 1).
  if (every_state_extrapolated && !porosity.empty()) {
    const double alpha_lines = microstructure::fit_bruggeman_exponent(porosity, tortuosity_extrapolated);
    if (std::isfinite(alpha_lines))
      out << "analysis_bruggeman_exponent_extrapolated = " << toml_float(alpha_lines)
          << "  # the same fit on the extrapolated tortuosities: with the line above, the exponent's bracket\n";
  }
  return out.str();
}

}  // namespace ellc::scenario
