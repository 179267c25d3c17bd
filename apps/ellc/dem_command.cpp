// `ellc dem SCENARIO.toml [-o DIR] [--threads N] [--restart CHECKPOINT] [--force] [--no-plot]`
// Packing generation + calendering with the built-in DEM engine (docs/engine.md).
// Outputs in DIR: timeseries.csv, summary.txt, pressure_thickness.png, vtk/, checkpoint.bin.
// `--seeds N [--jobs 2]` (or `[packing] seeds = [...]`): one run per packing seed in DIR/seed_<s>/,
// and DIR/ensemble_summary.{txt,csv}, DIR/pressure_thickness_ensemble.png (docs/engine.md,
// "Ensembles over packing seeds"). Exit code 1 when a member failed; the others still run.

#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "analyse_command.hpp"
#include "command_registry.hpp"
#include "ellc/io/input_error.hpp"
#include "ellc/scenario/ensemble.hpp"
#include "ellc/scenario/run_plan.hpp"
#include "ellc/scenario/scenario_runner.hpp"
#include "plot_runner.hpp"
#include "thread_policy.hpp"

namespace ellc::cli {
namespace {

struct DemOptions {
  std::string scenario_path;
  std::string output_directory;
  std::string restart_path;
  int threads = 0;
  bool force = false;
  bool no_plot = false;
  bool quiet = false;
  long long max_steps = 0;
  std::string seeds;           // --seeds N: an ensemble of N consecutive packing seeds
  std::string jobs;            // --jobs J: ensemble members side by side
  bool compare_hertz = false;  // --compare-hertz: the same packing again with plain Hertz
};

std::string clock_text(double seconds) {
  char text[32];
  const long total = static_cast<long>(seconds + 0.5);
  if (total >= 3600)
    std::snprintf(text, sizeof text, "%ldh%02ldm", total / 3600, (total / 60) % 60);
  else
    std::snprintf(text, sizeof text, "%ldm%02lds", total / 60, total % 60);
  return text;
}

// A bar with ETA on a terminal; a plain line every 10 % otherwise (logs, CI).
class Progress {
 public:
  explicit Progress(bool quiet) : quiet_(quiet), tty_(isatty(fileno(stderr)) != 0), start_(clock::now()) {}
  void update(const scenario::ScenarioRunner& runner) {
    if (quiet_) return;
    const double fraction = runner.progress();
    const double elapsed = std::chrono::duration<double>(clock::now() - start_).count();
    const double eta = fraction > 1e-3 ? elapsed * (1.0 - fraction) / fraction : 0.0;
    const auto& sim = runner.simulation();
    if (tty_) {
      constexpr int width = 30;
      const int filled = static_cast<int>(fraction * width);
      std::fprintf(stderr, "\r[%-*.*s] %5.1f%%  %-6s step %llu  p = %8.3g MPa  ETA %s   ", width, filled,
                   "##############################", 100.0 * fraction, scenario::phase_name(runner.state().phase),
                   static_cast<unsigned long long>(sim.step_count()), sim.wall_pressure(engine::kTopWall),
                   clock_text(eta).c_str());
      std::fflush(stderr);
    } else if (fraction >= next_report_ || runner.done()) {
      std::fprintf(stderr,
                   "ellc dem: %3.0f%%  %-6s step %llu  t = %.4g us  gap = %.4g um  p = %.4g MPa  elapsed %s  ETA %s\n",
                   100.0 * fraction, scenario::phase_name(runner.state().phase),
                   static_cast<unsigned long long>(sim.step_count()), sim.time(), sim.gap(),
                   sim.wall_pressure(engine::kTopWall), clock_text(elapsed).c_str(), clock_text(eta).c_str());
      while (next_report_ <= fraction) next_report_ += 0.1;
    }
  }
  void finish() {
    if (!quiet_ && tty_) std::fprintf(stderr, "\n");
  }
  [[nodiscard]] double seconds() const { return std::chrono::duration<double>(clock::now() - start_).count(); }

 private:
  using clock = std::chrono::steady_clock;
  bool quiet_;
  bool tty_;
  clock::time_point start_;
  double next_report_ = 0.0;
};

void print_summary(const scenario::RunSummary& s, const std::string& directory, double seconds) {
  std::printf(
      "ellc dem: %s after %llu steps (%.4g us simulated, dt = %.4g us, estimate %.4g us), %zu particles, %.1f s\n",
      s.finished ? "finished" : "stopped", static_cast<unsigned long long>(s.steps), s.time, s.dt, s.dt_estimate,
      s.particles, seconds);
  std::printf("  max pressure      %.6g MPa\n", s.max_pressure);
  std::printf("  loaded thickness  %.6g um  (porosity %.4f)\n", s.loaded_thickness, s.loaded_porosity);
  std::printf("  final thickness   %.6g um  (porosity %.4f)\n", s.final_thickness, s.final_porosity);
  std::printf("  springback        %.4g %%\n", s.springback_percent);
  std::printf("  plastic energy    %.6g pJ (%.6g pJ while calendering)\n", s.plastic_dissipation,
              s.plastic_dissipation_calendering);
  std::printf("  energy residual   %.4g pJ (%.2g %% of the work done)\n", s.energy_residual,
              100.0 * s.energy_residual_fraction);
  if (s.loaded_state_recorded)
    std::printf(
        "  beyond c_c/r^ = %.2g at the loaded state: %.1f %% of the pair force, %.1f %% of the plate force "
        "(largest %.3g)\n",
        s.loaded_validity.threshold, 100.0 * s.loaded_validity_shares.pair_force,
        100.0 * s.loaded_validity_shares.wall_force, s.loaded_validity.largest_ratio);
  if (s.narrow_phase_failures > 0)
    std::printf("  narrow phase      %llu failed evaluations (treated as no force)\n",
                static_cast<unsigned long long>(s.narrow_phase_failures));
  std::printf("  outputs in %s: timeseries.csv summary.txt vtk/ checkpoint.bin\n", directory.c_str());
}

// The last line of defence of the rule "finite numbers or an error" (docs/input_limits.md): the
// input bounds should make this unreachable, so a non-finite result is reported, not printed.
void check_finite_summary(const scenario::RunSummary& s, const std::string& source) {
  const std::pair<const char*, double> results[] = {{"max pressure", s.max_pressure},
                                                    {"loaded thickness", s.loaded_thickness},
                                                    {"final thickness", s.final_thickness},
                                                    {"springback", s.springback_percent},
                                                    {"porosity", s.final_porosity},
                                                    {"plastic energy", s.plastic_dissipation},
                                                    {"plate work", s.plate_work},
                                                    {"energy residual", s.energy_residual},
                                                    {"simulated time", s.time}};
  for (const auto& [name, value] : results)
    if (!std::isfinite(value))
      throw std::runtime_error(source + ": the run's " + name + " is " + format_number(value) +
                               ", not a finite number; an input beyond the bounds of docs/input_limits.md is the "
                               "likely cause (please report the scenario: the bounds should have caught it)");
}

scenario::RunSummary run_single(const DemOptions& options, scenario::Scenario loaded) {
  scenario::RunOptions run_options;
  run_options.output_directory = options.output_directory;
  run_options.restart_path = options.restart_path;
  run_options.force = options.force;
  Progress progress(options.quiet);
  scenario::ScenarioRunner runner(std::move(loaded), run_options);
  for (const auto& warning : runner.warnings()) std::fprintf(stderr, "ellc: warning: %s\n", warning.c_str());

  const std::uint64_t chunk = 100;
  std::uint64_t budget = options.max_steps > 0 ? static_cast<std::uint64_t>(options.max_steps) : ~std::uint64_t{0};
  while (!runner.done() && budget > 0) {
    const std::uint64_t steps = std::min(chunk, budget);
    runner.advance(steps);
    budget -= steps;
    progress.update(runner);
  }
  progress.finish();
  const std::string checkpoint = (std::filesystem::path(runner.output_directory()) / "checkpoint.bin").string();
  if (!runner.done()) runner.write_checkpoint(checkpoint);
  const scenario::RunSummary summary = runner.summary();
  check_finite_summary(summary, runner.scenario().source);
  runner.write_summary();
  print_summary(summary, runner.output_directory(), progress.seconds());
  std::fflush(stdout);  // the warnings after the summary they qualify, also when both go to one file
  for (const auto& warning : scenario::summary_warnings(summary))
    std::fprintf(stderr, "ellc: warning: %s\n", warning.c_str());
  if (!runner.done()) std::printf("  stopped at --max-steps; continue with --restart %s\n", checkpoint.c_str());
  if (!options.no_plot) {
    const auto directory = std::filesystem::path(runner.output_directory());
    const std::string png = (directory / "pressure_thickness.png").string();
    run_python_plot({"dem", (directory / "timeseries.csv").string(), png, "--title", options.scenario_path});
    std::printf("  plot: %s\n", png.c_str());
  }
  if (runner.scenario().analysis && runner.done()) analyse_run_states(runner, options.no_plot);  // [analysis]
  return summary;
}

// --compare-hertz: the same scenario (same packing, same protocol) with the normal law replaced
// by plain Hertz, into DIR/hertz; what plasticity changes, printed and in DIR/compare_hertz.txt.
void compare_with_hertz(const DemOptions& options, const scenario::Scenario& loaded, const scenario::RunSummary& law,
                        const std::string& directory) {
  scenario::Scenario hertz = loaded;
  hertz.contact.model.normal = NormalModel::hertz;
  DemOptions quiet = options;
  quiet.output_directory = (std::filesystem::path(directory) / "hertz").string();
  quiet.quiet = true;
  quiet.no_plot = true;
  quiet.restart_path.clear();
  std::printf("== the same packing with plain Hertz (--compare-hertz), into %s\n", quiet.output_directory.c_str());
  const scenario::RunSummary elastic = run_single(quiet, std::move(hertz));
  const auto row = [](const char* name, double a, double b, const char* unit) {
    char text[160];
    std::snprintf(text, sizeof text, "%-26s %12.6g %12.6g  %s\n", name, a, b, unit);
    return std::string(text);
  };
  std::string table = "# ellc dem --compare-hertz: " + options.scenario_path + "\n";
  table += "#                          becker_kamlah        hertz\n";
  table += row("springback", law.springback_percent, elastic.springback_percent, "%");
  table += row("loaded_thickness", law.loaded_thickness, elastic.loaded_thickness, "um");
  table += row("final_thickness", law.final_thickness, elastic.final_thickness, "um");
  table += row("held_pressure", law.held_pressure, elastic.held_pressure, "MPa");
  table += row("plastic_dissipation", law.plastic_dissipation, elastic.plastic_dissipation, "pJ");
  table += row("plate_work", law.plate_work, elastic.plate_work, "pJ (net over the cycle: what was dissipated)");
  table += row("plastic_share_of_work", law.plate_work > 0 ? law.plastic_dissipation / law.plate_work : 0.0,
               elastic.plate_work > 0 ? elastic.plastic_dissipation / elastic.plate_work : 0.0, "");
  std::printf("%s", table.c_str());
  std::ofstream((std::filesystem::path(directory) / "compare_hertz.txt").string()) << table;
}

// The whole of `text` as an integer, or an InputError naming the option.
long long integer_option(const char* option, const std::string& text, const std::string& expected) {
  long long value = 0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (text.empty() || error != std::errc{} || stop != end) throw InputError("", option, text, expected);
  return value;
}

// One run per packing seed (scenario/ensemble.hpp); the plots are drawn here, after all members
// have run, from this thread alone (the plot runner forks).
void run_members(const DemOptions& options, const scenario::Scenario& loaded, const std::vector<std::uint64_t>& seeds,
                 int jobs) {
  using scenario::EnsembleMember;
  using scenario::ScenarioRunner;
  const auto start = std::chrono::steady_clock::now();
  for (const auto& warning : loaded.warnings) std::fprintf(stderr, "ellc: warning: %s\n", warning.c_str());
  scenario::EnsembleOptions ensemble;
  ensemble.run.output_directory = options.output_directory;
  ensemble.run.force = options.force;
  ensemble.jobs = jobs;
  const bool one_at_a_time = std::min<std::size_t>(static_cast<std::size_t>(jobs), seeds.size()) == 1;
  std::unique_ptr<Progress> progress;  // the bar of a single run, when members run one at a time
  ensemble.on_member_start = [&](const EnsembleMember& member) {
    if (!options.quiet)
      std::fprintf(stderr, "ellc dem: member %zu/%zu, packing seed %llu -> %s\n", member.index + 1, seeds.size(),
                   static_cast<unsigned long long>(member.seed), member.directory.c_str());
    if (one_at_a_time) progress = std::make_unique<Progress>(options.quiet);
  };
  if (one_at_a_time)
    ensemble.on_progress = [&](const EnsembleMember&, const ScenarioRunner& runner) { progress->update(runner); };
  ensemble.on_member_end = [&](const EnsembleMember& member, const ScenarioRunner*) {
    if (progress) progress->finish();
    for (const auto& warning : member.warnings)
      if (std::find(loaded.warnings.begin(), loaded.warnings.end(), warning) == loaded.warnings.end())
        std::fprintf(stderr, "ellc: warning: packing seed %llu: %s\n", static_cast<unsigned long long>(member.seed),
                     warning.c_str());
    const auto seed = static_cast<unsigned long long>(member.seed);
    if (member.finished)
      std::printf(
          "ellc dem: seed %llu finished: %llu steps, max pressure %.6g MPa, loaded %.6g um, final %.6g um, "
          "springback %.4g %%, %.1f s\n",
          seed, static_cast<unsigned long long>(member.summary.steps), member.summary.max_pressure,
          member.summary.loaded_thickness, member.summary.final_thickness, member.summary.springback_percent,
          member.seconds);
    else
      std::printf("ellc dem: seed %llu FAILED after %.1f s: %s\n", seed, member.seconds, member.error.c_str());
    std::fflush(stdout);
  };
  const scenario::EnsembleResult result = scenario::run_ensemble(loaded, seeds, ensemble);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::printf("\nellc dem: ensemble of %zu packing seeds: %zu finished, %zu failed, %.1f s\n", result.members.size(),
              result.finished_count(), result.failed_count(), seconds);
  std::ostringstream table;
  scenario::write_ensemble_summary_text(table, result);
  std::fputs(table.str().c_str(), stdout);
  const auto directory = std::filesystem::path(result.directory);
  const bool plot = !options.no_plot && result.finished_count() > 0;
  std::printf("outputs in %s: ensemble_summary.txt ensemble_summary.csv%s, and seed_<seed>/ per member\n",
              result.directory.c_str(), plot ? " pressure_thickness_ensemble.png" : "");
  std::fflush(stdout);

  std::string plot_error;
  if (plot) {
    try {
      std::vector<std::string> ensemble_plot{"dem-ensemble", (directory / "pressure_thickness_ensemble.png").string(),
                                             "--title", options.scenario_path};
      for (const EnsembleMember& member : result.members) {
        if (!member.finished) continue;
        const auto member_directory = std::filesystem::path(member.directory);
        const std::string csv = (member_directory / "timeseries.csv").string();
        run_python_plot({"dem", csv, (member_directory / "pressure_thickness.png").string(), "--title",
                         options.scenario_path + ", packing seed " + std::to_string(member.seed)});
        ensemble_plot.push_back(csv);
      }
      run_python_plot(ensemble_plot);
    } catch (const std::exception& error) {
      plot_error = error.what();
    }
  }
  if (result.failed_count() > 0 || !plot_error.empty()) {
    std::string message;
    if (result.failed_count() > 0)
      message = std::to_string(result.failed_count()) + " of " + std::to_string(result.members.size()) +
                " ensemble members failed (listed in " + (directory / "ensemble_summary.txt").string() + "; " +
                (result.finished_count() > 0
                     ? "the statistics are over the " + std::to_string(result.finished_count()) + " that finished)"
                     : "none finished, so there are no statistics)");
    if (!plot_error.empty()) message += (message.empty() ? "" : "; ") + plot_error;
    throw std::runtime_error(message);
  }
}

// The planned work (scenario/run_plan.hpp), printed before anything is built; beyond the stated
// limits only with --force, and never what the engine cannot represent.
void check_plan(const DemOptions& options, const scenario::Scenario& loaded) {
  const scenario::RunPlan plan = scenario::plan_run(loaded);
  if (!options.quiet) std::fprintf(stderr, "ellc dem: plan: %s\n", scenario::describe_plan(plan).c_str());
  if (!plan.impossible.empty())
    throw InputError(loaded.source, plan.impossible.front() + " (refused even with --force)");
  if (plan.beyond_limits.empty()) return;
  if (!options.force)
    throw InputError(loaded.source, plan.beyond_limits.front() + "; run with --force to start it anyway");
  for (const auto& reason : plan.beyond_limits)
    std::fprintf(stderr, "ellc: warning: %s; running anyway (--force)\n", reason.c_str());
}

void run_dem(const DemOptions& options) {
  prefer_short_spinning();
#ifdef _OPENMP
  if (options.threads > 0) omp_set_num_threads(options.threads);
#endif
  scenario::Scenario loaded = scenario::read_scenario(options.scenario_path);
  check_plan(options, loaded);
  std::optional<long long> count;
  if (!options.seeds.empty())
    count = integer_option(
        "--seeds", options.seeds,
        "a number of packing seeds, an integer in [1, " + std::to_string(scenario::kMaxEnsembleMembers) + "]");
  int jobs = 1;
  if (!options.jobs.empty()) {
    const long long value =
        integer_option("--jobs", options.jobs, "a number of members run side by side, an integer >= 1");
    if (value < 1)
      throw InputError("", "--jobs", options.jobs, "a number of members run side by side, an integer >= 1");
    jobs = static_cast<int>(std::min<long long>(value, static_cast<long long>(scenario::kMaxEnsembleMembers)));
  }
  // A checkpoint continues one run, also one member of an ensemble (its packing is in the checkpoint).
  if (!options.restart_path.empty()) {
    if (count)
      throw InputError("", "--restart", options.restart_path,
                       "no --seeds with --restart: continue one member on its own, with -o DIR/seed_<s> "
                       "--restart DIR/seed_<s>/checkpoint.bin");
    run_single(options, std::move(loaded));
    return;
  }
  const std::vector<std::uint64_t> seeds = scenario::ensemble_seeds(loaded, count);
  if (seeds.empty()) {
    if (!options.jobs.empty())
      throw InputError("", "--jobs", options.jobs,
                       "--seeds N or [packing] seeds with it: --jobs runs the members of an ensemble side by side "
                       "(-j sets the threads of one run)");
    if (options.compare_hertz && (options.max_steps > 0 || !options.restart_path.empty()))
      throw InputError("", "--compare-hertz", "with --max-steps or --restart",
                       "a whole run from a fresh packing (the Hertz run repeats it)");
    const scenario::Scenario copy = options.compare_hertz ? loaded : scenario::Scenario{};
    const scenario::RunSummary law = run_single(options, std::move(loaded));
    if (options.compare_hertz && law.finished) {
      const std::string directory = options.output_directory.empty() ? copy.output.directory : options.output_directory;
      compare_with_hertz(options, copy, law, directory);
    }
    return;
  }
  if (options.compare_hertz)
    throw InputError("", "--compare-hertz", "with an ensemble", "a single run (compare members one at a time)");
  if (options.max_steps > 0)
    throw InputError("", "--max-steps", std::to_string(options.max_steps),
                     "no --max-steps for an ensemble (every member runs to the end of the protocol)");
  if (jobs > 1 && options.threads > 1)
    throw InputError("", "--threads", std::to_string(options.threads),
                     "1, or no --threads, with --jobs " + std::to_string(jobs) +
                         ": members that run side by side use one engine thread each");
  run_members(options, loaded, seeds, jobs);
}

const RegisterCommand registration([](CLI::App& root) {
  auto options = std::make_shared<DemOptions>();
  CLI::App* command = root.add_subcommand("dem", "Generate and calender an ellipsoid packing with the built-in DEM");
  command->add_option("scenario", options->scenario_path, "Scenario file (TOML), e.g. examples/calendering.toml")
      ->required();
  command->add_option("-o,--output,--output-dir", options->output_directory,
                      "Output directory (overrides [output].directory)");
  command->add_option("-j,--threads", options->threads, "OpenMP threads (results do not depend on it)")
      ->check(CLI::PositiveNumber);
  command->add_option("--restart", options->restart_path, "Continue from a checkpoint written by this scenario");
  command->add_flag("--force", options->force,
                    "Run with a time step above the stability estimate, or beyond the planned-work limits "
                    "(steps, memory, output; docs/input_limits.md)");
  command->add_flag("--no-plot", options->no_plot, "Skip the PNG (no Python needed)");
  command->add_flag("-q,--quiet", options->quiet, "No progress output");
  command->add_option("--max-steps", options->max_steps, "Stop after this many steps and write a checkpoint")
      ->check(CLI::PositiveNumber);
  command->add_option(
      "--seeds", options->seeds,
      "Run an ensemble: N packing seeds from [packing] seed (seed, seed+1, ...), each in DIR/seed_<s>/");
  command->add_flag("--compare-hertz", options->compare_hertz,
                    "Run the same packing again with plain Hertz and compare springback and energies");
  command->add_option("--jobs", options->jobs, "Ensemble members run side by side (default 1; one engine thread each)");
  command->callback([options] { run_dem(*options); });
});

}  // namespace
}  // namespace ellc::cli
