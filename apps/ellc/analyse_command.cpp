// `ellc analyse CHECKPOINT_OR_PACKING [-o DIR] [--scenario S.toml] [--voxels-per-semi-axis N |
// --spacing H] [--memory-limit-gib G] [--coarse-factor F] [--no-plot]`
// The microstructure of a packing (docs/microstructure.md): voxels (.vti, .npy), porosity and
// contact profiles, the continuous pore-size distribution, the tortuosity factor along x, y, z at
// two resolutions, and the force network (.vtp) with its normal-force PDF. A packing file (.csv)
// is read as it is; anything else is taken for a checkpoint of `ellc dem`, which needs the
// scenario that wrote it (--scenario, or the one named in summary.txt next to the checkpoint).

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "analyse_command.hpp"
#include "command_registry.hpp"
#include "ellc/io/input_error.hpp"
#include "ellc/microstructure/analysis.hpp"
#include "ellc/scenario/state_analysis.hpp"
#include "plot_runner.hpp"
#include "thread_policy.hpp"

namespace ellc::cli {

microstructure::AnalysisReport analyse_into(const microstructure::Packing& packing,
                                            const microstructure::AnalysisOptions& options,
                                            const std::string& directory, const std::string& source,
                                            const std::string& title, bool no_plot) {
  const auto start = std::chrono::steady_clock::now();
  microstructure::AnalysisReport report = microstructure::analyse(packing, options, source);
  microstructure::write_analysis(directory, packing, report);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("ellc analyse: %s -> %s (%.1f s)\n", source.c_str(), directory.c_str(), seconds);
  std::ostringstream summary;
  microstructure::write_analysis_summary(summary, report);
  std::istringstream lines(summary.str());
  for (std::string line; std::getline(lines, line);) std::printf("  %s\n", line.c_str());
  std::fflush(stdout);
  if (!no_plot) run_python_plot({"analysis", directory, "--title", title});
  return report;
}

void analyse_run_states(const scenario::ScenarioRunner& runner, bool no_plot) {
  const scenario::Scenario& loaded = runner.scenario();
  const microstructure::AnalysisOptions options = scenario::analysis_options(loaded);
  const std::filesystem::path directory(runner.output_directory());
  std::vector<scenario::StateAnalysis> states;
  std::vector<std::string> folders;
  const auto analyse_state = [&](const std::string& state, const microstructure::Packing& packing) {
    const std::string folder = (directory / ("analysis_" + state)).string();
    std::printf("== microstructure of the %s state ([analysis])\n", state.c_str());
    states.push_back({state, analyse_into(packing, options, folder, loaded.source + " (" + state + ")",
                                          loaded.source + ", " + state + " state", no_plot)});
    folders.push_back(folder);
  };
  if (const auto& packing = runner.loaded_packing()) analyse_state("loaded", *packing);
  analyse_state("released", scenario::packing_of(runner.simulation()));
  const std::string summary = scenario::states_summary(states);
  std::printf("%s", summary.c_str());
  std::ofstream((directory / "summary.txt").string(), std::ios::app) << summary;
  if (!no_plot) {
    std::vector<std::string> arguments{"tortuosity-porosity", (directory / "tortuosity_porosity.png").string(),
                                       "--title", loaded.source};
    arguments.insert(arguments.end(), folders.begin(), folders.end());
    run_python_plot(arguments);
  }
  std::fflush(stdout);
}

namespace {

struct AnalyseOptions {
  std::string input;
  std::string output_directory;
  std::string scenario_path;
  double voxels_per_semi_axis = 5.0;
  double spacing = 0.0;
  bool spacing_given = false;  // --spacing 0 is refused, not read as "unset"
  double memory_limit_gib = 4.0;
  double coarse_factor = 2.0;
  std::string axes = "xyz";
  bool no_plot = false;
};

// The scenario named in the first line of summary.txt next to a checkpoint ("# ellc dem summary: S").
std::string scenario_beside(const std::string& checkpoint) {
  const auto summary = std::filesystem::path(checkpoint).parent_path() / "summary.txt";
  std::ifstream in(summary);
  std::string line;
  const std::string prefix = "# ellc dem summary: ";
  if (in && std::getline(in, line) && line.rfind(prefix, 0) == 0) return line.substr(prefix.size());
  return {};
}

void run_analyse(const AnalyseOptions& options) {
  prefer_short_spinning();
  cap_threads_at_cpu_quota();
  const std::filesystem::path input(options.input);
  microstructure::Packing packing;
  if (input.extension() == ".csv") {
    packing = microstructure::read_packing_file(options.input);
  } else {
    std::string scenario = options.scenario_path.empty() ? scenario_beside(options.input) : options.scenario_path;
    if (scenario.empty() || !std::filesystem::exists(scenario))
      throw InputError(options.input, "--scenario", scenario.empty() ? "none" : scenario,
                       "the scenario file that wrote this checkpoint (--scenario S.toml; summary.txt next to the "
                       "checkpoint names it), or a packing file (.csv)");
    packing = scenario::read_checkpoint_packing(options.input, scenario);
  }
  microstructure::AnalysisOptions analysis;
  if (!(options.voxels_per_semi_axis > 0.0))
    throw InputError("", "--voxels-per-semi-axis", format_number(options.voxels_per_semi_axis), "a number > 0");
  if (options.spacing_given && !(std::isfinite(options.spacing) && options.spacing > 0.0))
    throw InputError("", "--spacing", format_number(options.spacing), "a voxel size > 0 (µm)");
  if (!(options.memory_limit_gib > 0.0))
    throw InputError("", "--memory-limit-gib", format_number(options.memory_limit_gib), "a number of GiB > 0");
  if (!(options.coarse_factor >= 1.0))
    throw InputError("", "--coarse-factor", format_number(options.coarse_factor), "a factor >= 1 (1: none)");
  analysis.resolution.voxels_per_semi_axis = options.voxels_per_semi_axis;
  analysis.resolution.spacing = options.spacing;
  analysis.resolution.memory_limit_bytes = options.memory_limit_gib * 1024.0 * 1024.0 * 1024.0;
  analysis.coarse_factor = options.coarse_factor;
  if (options.axes.empty() || options.axes.find_first_not_of("xyz") != std::string::npos)
    throw InputError("", "--axes", options.axes, "the tortuosity directions, some of x, y, z (e.g. z or xyz)");
  for (std::size_t axis = 0; axis < 3; ++axis)
    analysis.tortuosity_axes[axis] = options.axes.find("xyz"[axis]) != std::string::npos;
  const std::string directory = options.output_directory.empty()
                                    ? (input.parent_path() / (input.stem().string() + "_analysis")).string()
                                    : options.output_directory;
  (void)analyse_into(packing, analysis, directory, options.input, options.input, options.no_plot);
}

const RegisterCommand registration([](CLI::App& root) {
  auto options = std::make_shared<AnalyseOptions>();
  CLI::App* command = root.add_subcommand(
      "analyse", "Microstructure of a packing: voxels, porosity profile, pore sizes, tortuosity, force network");
  command->add_option("input", options->input, "A checkpoint of ellc dem, or a packing file (.csv)")->required();
  command->add_option("-o,--output", options->output_directory, "Output directory (default: INPUT_STEM_analysis)");
  command->add_option("--scenario", options->scenario_path,
                      "The scenario that wrote the checkpoint (default: the one summary.txt beside it names)");
  command->add_option("--voxels-per-semi-axis", options->voxels_per_semi_axis,
                      "Resolution: voxels per smallest semi-axis (default 5)");
  CLI::Option* spacing =
      command->add_option("--spacing", options->spacing, "Resolution: voxel size in µm (overrides the above)");
  command->add_option("--memory-limit-gib", options->memory_limit_gib,
                      "Refuse grids whose analysis needs more (default 4 GiB)");
  command->add_option("--coarse-factor", options->coarse_factor,
                      "The resolution check: tortuosity and pore radii again at this x the voxel size, and tortuosity "
                      "extrapolated to zero voxel size (default 2; 1: none)");
  command->add_option("--axes", options->axes, "Tortuosity directions, some of x, y, z (default xyz)");
  command->add_flag("--no-plot", options->no_plot, "Skip the PNGs (no Python needed)");
  command->callback([options, spacing] {
    options->spacing_given = spacing->count() > 0;
    run_analyse(*options);
  });
});

}  // namespace
}  // namespace ellc::cli
