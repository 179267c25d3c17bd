// `ellc dem SCENARIO.toml [-o DIR] [--threads N] [--restart CHECKPOINT] [--force] [--no-plot]`
// Packing generation + calendering with the built-in DEM engine (docs/engine.md).
// Outputs in DIR: timeseries.csv, summary.txt, pressure_thickness.png, vtk/, checkpoint.bin.
// `--seeds N [--jobs 2]` (or `[packing] seeds = [...]`): one run per packing seed in DIR/seed_<s>/,
// and DIR/ensemble_summary.{txt,csv}, DIR/pressure_thickness_ensemble.png (docs/engine.md,
// "Ensembles over packing seeds"). Exit code 1 when a member failed; the others still run.
// `--compare hertz,thornton` (`--compare-hertz` = `--compare hertz`): the same packing again with
// each named law, in DIR/<law>/, tabulated in DIR/compare_<laws>.txt (docs/engine.md, "What the
// law changes"). `--check`: read and validate the scenario, print the plan, run nothing.

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
#include "ellc/engine/cpu_load.hpp"
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
  std::string seeds;                   // --seeds N: an ensemble of N consecutive packing seeds
  std::string jobs;                    // --jobs J: ensemble members side by side
  bool compare_hertz = false;          // --compare-hertz: the same packing again with plain Hertz
  std::string compare;                 // --compare LAW[,LAW]: the same packing again with each law
  bool check = false;                  // --check: validate the scenario and print its plan only
  std::vector<std::string> overrides;  // --set KEY=VALUE: scenario entries replaced before validation
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
  std::printf("  plastic share     %.4g %% of the plate work (%.6g pJ)\n", 100.0 * s.plastic_share_of_plate_work(),
              s.plate_work);
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

// The laws `--compare` runs the same scenario with (same packing, same protocol), each a change of
// the scenario's contact model.
struct ComparedLaw {
  const char* name;
  const char* description;
  void (*apply)(scenario::Scenario&);
};
constexpr ComparedLaw kComparedLaws[] = {
    {"hertz", "plain Hertz (normal = \"hertz\": no plasticity)",
     [](scenario::Scenario& s) { s.contact.model.normal = NormalModel::hertz; }},
    {"thornton", "Thornton's elastic-perfectly-plastic law (lambda = 1.6: m = 0, p = 1.6, docs/model.md Sec. 4)",
     [](scenario::Scenario& s) {
       s.contact.model.normal = NormalModel::becker_kamlah;  // also when the scenario's own law is Hertz
       s.contact.model.law = s.contact.model.law.elastic_fully_plastic();
     }},
};

std::string compared_law_names() {
  std::string names;
  for (const ComparedLaw& law : kComparedLaws) names += (names.empty() ? "" : ", ") + std::string(law.name);
  return names;
}

// --compare's comma-separated list (and --compare-hertz), each law once, in the order given.
std::vector<const ComparedLaw*> compared_laws(const DemOptions& options) {
  std::vector<const ComparedLaw*> laws;
  const std::string expected = "a comma-separated list of laws, each once, from: " + compared_law_names();
  const auto add = [&](const std::string& name) {
    const auto* law = std::find_if(std::begin(kComparedLaws), std::end(kComparedLaws),
                                   [&](const ComparedLaw& known) { return name == known.name; });
    if (law == std::end(kComparedLaws) || std::find(laws.begin(), laws.end(), law) != laws.end())
      throw InputError("", "--compare", options.compare, expected);
    laws.push_back(law);
  };
  if (options.compare_hertz) add("hertz");
  if (options.compare.empty()) return laws;
  std::size_t begin = 0;
  while (true) {
    const std::size_t comma = options.compare.find(',', begin);
    const std::string name = options.compare.substr(begin, comma == std::string::npos ? comma : comma - begin);
    if (!(options.compare_hertz && name == "hertz")) add(name);  // --compare-hertz --compare hertz: once
    if (comma == std::string::npos) break;
    begin = comma + 1;
  }
  return laws;
}

// The rows of the --compare table: a figure of each run's summary.
struct ComparedFigure {
  const char* name;
  double (*of)(const scenario::RunSummary&);
  const char* unit;
};
using Summary = scenario::RunSummary;
constexpr ComparedFigure kComparedFigures[] = {
    {"springback", [](const Summary& s) { return s.springback_percent; }, "%"},
    {"loaded_thickness", [](const Summary& s) { return s.loaded_thickness; }, "um"},
    {"loaded_porosity", [](const Summary& s) { return s.loaded_porosity; }, ""},
    {"final_thickness", [](const Summary& s) { return s.final_thickness; }, "um"},
    {"final_porosity", [](const Summary& s) { return s.final_porosity; }, ""},
    {"max_pressure", [](const Summary& s) { return s.max_pressure; }, "MPa"},
    {"held_pressure", [](const Summary& s) { return s.held_pressure; }, "MPa"},
    {"plastic_dissipation", [](const Summary& s) { return s.plastic_dissipation; }, "pJ"},
    {"plate_work", [](const Summary& s) { return s.plate_work; }, "pJ (net over the cycle: what was dissipated)"},
    {"plastic_share_of_plate_work", [](const Summary& s) { return s.plastic_share_of_plate_work(); }, ""},
    {"energy_residual_fraction", [](const Summary& s) { return s.energy_residual_fraction; }, ""},
    {"narrow_phase_failures", [](const Summary& s) { return static_cast<double>(s.narrow_phase_failures); }, ""},
};

// The same packing with each law into DIR/<law>; what the scenario's law changes, printed, in
// DIR/compare_<law>[_<law>].txt (compare_hertz.txt for --compare-hertz), and the loading curves
// of all laws in DIR/pressure_thickness_compare.png. A law whose run fails (e.g. it cannot reach
// the target pressure) is named in the table and the error, and the others are still compared.
void compare_laws(const DemOptions& options, const scenario::Scenario& loaded, const Summary& law,
                  const std::vector<const ComparedLaw*>& laws, const std::string& directory) {
  const std::string own_name(name_of(loaded.contact.model.normal));
  std::vector<std::pair<std::string, Summary>> runs{{own_name, law}};
  std::vector<std::string> failures;  // "law: message"
  std::string file_name = "compare";
  for (const ComparedLaw* compared : laws) {
    scenario::Scenario variant = loaded;
    compared->apply(variant);
    DemOptions quiet = options;
    quiet.output_directory = (std::filesystem::path(directory) / compared->name).string();
    quiet.quiet = true;
    quiet.no_plot = true;
    quiet.restart_path.clear();
    std::printf("== the same packing with %s (--compare), into %s\n", compared->description,
                quiet.output_directory.c_str());
    std::fflush(stdout);
    file_name += std::string("_") + compared->name;
    try {
      runs.emplace_back(compared->name, run_single(quiet, std::move(variant)));
    } catch (const std::exception& error) {
      std::printf("ellc dem: --compare %s failed: %s\n", compared->name, error.what());
      failures.push_back(std::string(compared->name) + ": " + error.what());
    }
  }
  std::string table = "# ellc dem --compare: " + options.scenario_path + "\n# " + std::string(26, ' ');
  char text[64];
  for (const auto& run : runs) {
    std::snprintf(text, sizeof text, " %16s", run.first.c_str());
    table += text;
  }
  table += "\n";
  for (const ComparedFigure& figure : kComparedFigures) {
    std::snprintf(text, sizeof text, "%-28s", figure.name);
    table += text;
    for (const auto& run : runs) {
      std::snprintf(text, sizeof text, " %16.7g", figure.of(run.second));
      table += text;
    }
    table += std::string("  ") + figure.unit + "\n";
  }
  for (const std::string& failure : failures) table += "# failed, not in the table: " + failure + "\n";
  std::printf("%s", table.c_str());
  const auto base = std::filesystem::path(directory);
  std::ofstream((base / (file_name + ".txt")).string()) << table;
  std::printf("  table: %s\n", (base / (file_name + ".txt")).string().c_str());
  if (!options.no_plot) {
    std::vector<std::string> plot{"dem-compare", (base / "pressure_thickness_compare.png").string(), "--title",
                                  options.scenario_path, (base / "timeseries.csv").string()};
    std::string labels = own_name;
    for (std::size_t index = 1; index < runs.size(); ++index) {  // the laws that finished
      plot.push_back((base / runs[index].first / "timeseries.csv").string());
      labels += "," + runs[index].first;
    }
    plot.insert(plot.end(), {"--labels", labels});
    run_python_plot(plot);
    std::printf("  plot: %s\n", (base / "pressure_thickness_compare.png").string().c_str());
  }
  if (!failures.empty())
    throw std::runtime_error("--compare: " + std::to_string(failures.size()) + " of " + std::to_string(laws.size()) +
                             " compared laws failed (" + failures.front() + (failures.size() > 1 ? "; ..." : "") +
                             "); " + (base / (file_name + ".txt")).string() + " holds the others");
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
scenario::RunPlan check_plan(const DemOptions& options, const scenario::Scenario& loaded) {
  scenario::RunPlan plan = scenario::plan_run(loaded);
  if (!options.quiet && !options.check)  // --check prints it as its result
    std::fprintf(stderr, "ellc dem: plan: %s\n", scenario::describe_plan(plan).c_str());
  if (!plan.impossible.empty())
    throw InputError(loaded.source, plan.impossible.front() + " (refused even with --force)");
  if (plan.beyond_limits.empty()) return plan;
  if (!options.force)
    throw InputError(loaded.source, plan.beyond_limits.front() + "; run with --force to start it anyway");
  for (const auto& reason : plan.beyond_limits)
    std::fprintf(stderr, "ellc: warning: %s; running anyway (--force)\n", reason.c_str());
  return plan;
}

void run_dem(const DemOptions& options) {
  prefer_short_spinning();
#ifdef _OPENMP
  if (options.threads > 0) omp_set_num_threads(options.threads);
#endif
  if (options.threads <= 0) cap_threads_at_cpu_quota();
  scenario::Scenario loaded = scenario::read_scenario(options.scenario_path, options.overrides);
  const std::vector<const ComparedLaw*> laws = compared_laws(options);
  const scenario::RunPlan plan = check_plan(options, loaded);
  if (options.check) {
    std::printf("ellc dem: %s is valid: %s\n", loaded.source.c_str(), scenario::describe_plan(plan).c_str());
    for (const auto& warning : loaded.warnings) std::fprintf(stderr, "ellc: warning: %s\n", warning.c_str());
    return;
  }
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
    if (!laws.empty())
      throw InputError("", "--compare", options.compare_hertz ? "hertz" : options.compare,
                       "no --compare with --restart: a compared law repeats the whole run from a fresh packing");
    run_single(options, std::move(loaded));
    return;
  }
  const std::vector<std::uint64_t> seeds = scenario::ensemble_seeds(loaded, count);
  if (seeds.empty()) {
    if (!options.jobs.empty())
      throw InputError("", "--jobs", options.jobs,
                       "--seeds N or [packing] seeds with it: --jobs runs the members of an ensemble side by side "
                       "(-j sets the threads of one run)");
    if (!laws.empty() && options.max_steps > 0)
      throw InputError("", "--compare", "with --max-steps",
                       "a whole run from a fresh packing (each compared law repeats it)");
    const scenario::Scenario copy = laws.empty() ? scenario::Scenario{} : loaded;
    const scenario::RunSummary law = run_single(options, std::move(loaded));
    if (!laws.empty() && law.finished) {
      const std::string directory = options.output_directory.empty() ? copy.output.directory : options.output_directory;
      compare_laws(options, copy, law, laws, directory);
    }
    return;
  }
  if (!laws.empty())
    throw InputError("", "--compare", "with an ensemble", "a single run (compare members one at a time)");
  if (options.max_steps > 0)
    throw InputError("", "--max-steps", std::to_string(options.max_steps),
                     "no --max-steps for an ensemble (every member runs to the end of the protocol)");
  if (jobs > 1 && options.threads > 1)
    throw InputError("", "--threads", std::to_string(options.threads),
                     "1, or no --threads, with --jobs " + std::to_string(jobs) +
                         ": members that run side by side use one engine thread each");
  // Members side by side beyond a CPU quota only share it (docs/engine.md, "Threads"): said, not
  // changed, since the user chose the count.
  const auto quota = engine::process_cpu_quota();
  if (const int within = engine::threads_within_quota(jobs, quota); within < jobs)
    std::fprintf(stderr,
                 "ellc: warning: --jobs %d under a CPU quota of %s core(s): the members share it, each running "
                 "slower; --jobs %d would take about as long with less memory\n",
                 jobs, format_number(quota.value_or(0.0)).c_str(), within);
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
  command->add_flag("--compare-hertz", options->compare_hertz, "The same as --compare hertz");
  command->add_option("--compare", options->compare,
                      "Run the same packing again with each law (hertz, thornton; comma-separated) and compare "
                      "springback, thickness, plastic share and energies");
  command->add_flag("--check", options->check, "Read and validate the scenario, print its plan, run nothing");
  command->add_option("--jobs", options->jobs, "Ensemble members run side by side (default 1; one engine thread each)");
  add_scenario_overrides(*command, options->overrides);
  command->callback([options] { run_dem(*options); });
});

}  // namespace
}  // namespace ellc::cli
