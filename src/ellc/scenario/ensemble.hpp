#pragma once
// An ensemble over packing seeds (`ellc dem SCENARIO --seeds N`, or `[packing] seeds = [...]`):
// the same scenario run once per seed, each member writing into DIR/seed_<s>/ exactly what a
// single run writes, and DIR/ensemble_summary.{txt,csv} with the mean, the sample standard
// deviation, the min and the max of every numeric figure of the members' summary.txt.
// docs/engine.md, "Ensembles over packing seeds".
//
// The statistics are read from the members' `key = value` summary lines (write_summary_lines),
// not from RunSummary's fields, so a figure added to summary.txt is in the ensemble's table
// without a change here.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "ellc/io/table_reader.hpp"
#include "ellc/scenario/run_outputs.hpp"
#include "ellc/scenario/scenario.hpp"
#include "ellc/scenario/scenario_runner.hpp"

namespace ellc::scenario {

inline constexpr std::size_t kMaxEnsembleMembers = 1000;

// `[packing] seeds` of a scenario file (empty when the key is absent): integers >= 0, 1 to
// kMaxEnsembleMembers of them, all different, and not together with `seed`. Throws InputError
// naming packing.seeds (or the element packing.seeds[i]), the value and what was expected.
[[nodiscard]] std::vector<std::uint64_t> read_packing_seeds(TableReader& packing);

// The seeds of the run: `count` consecutive seeds from [packing] seed (`--seeds N`: seed, seed+1,
// ..., seed+N-1), or the scenario's packing.seeds. Empty: a single run (neither given). Throws
// InputError for a count outside [1, kMaxEnsembleMembers] or for both a count and a list.
[[nodiscard]] std::vector<std::uint64_t> ensemble_seeds(const Scenario& scenario, std::optional<long long> count);

// DIR/seed_<seed>.
[[nodiscard]] std::string member_directory(const std::string& ensemble_directory, std::uint64_t seed);

struct EnsembleMember {
  std::size_t index = 0;
  std::uint64_t seed = 0;
  std::string directory;              // DIR/seed_<seed> ("" for runs in memory)
  bool finished = false;              // ran to the end of the protocol
  std::string error;                  // why it failed (empty when finished)
  RunSummary summary;                 // when finished
  std::string summary_text;           // its summary.txt lines, when finished
  std::vector<std::string> warnings;  // the runner's (the scenario's own and, e.g., --force)
  double seconds = 0.0;               // wall clock
};

// One figure over the finished members: the members that have a finite number for it (n), their
// mean, sample standard deviation sqrt(sum (x - mean)^2 / (n - 1)) (NaN for n = 1), standard
// error sd / sqrt(n), min and max.
struct FigureStatistics {
  std::string name;  // the summary.txt key, e.g. springback_percent
  std::size_t count = 0;
  double mean = 0.0;
  double sd = 0.0;
  double standard_error = 0.0;
  double min = 0.0;
  double max = 0.0;
};

// Every key of the `key = value` lines whose value is a number (true/false and text are not),
// in the order of first appearance; `#` lines are comments. Non-finite values are left out of
// that key's statistics.
[[nodiscard]] std::vector<FigureStatistics> summary_statistics(const std::vector<std::string>& summary_texts);

struct EnsembleOptions {
  // For every member. output_directory is the ensemble's DIR (empty: [output].directory); each
  // member writes into DIR/seed_<s>. write_files = false runs everything in memory.
  RunOptions run;
  // Members run side by side (threads). Above 1, each member's engine runs on one thread
  // (parallel_threshold is lifted), so the results do not depend on it.
  int jobs = 1;
  std::uint64_t steps_per_progress = 100;
  // Called one at a time (under a lock), from the thread that runs the member; must not throw.
  std::function<void(const EnsembleMember&)> on_member_start;
  std::function<void(const EnsembleMember&, const ScenarioRunner&)> on_progress;  // every steps_per_progress steps
  // At the member's end, finished or failed; the runner is null when it could not be built.
  std::function<void(const EnsembleMember&, const ScenarioRunner*)> on_member_end;
};

struct EnsembleResult {
  std::string source;     // the scenario file
  std::string directory;  // DIR
  std::vector<EnsembleMember> members;       // in seed order
  std::vector<FigureStatistics> statistics;  // over the finished members
  [[nodiscard]] std::size_t finished_count() const noexcept;
  [[nodiscard]] std::size_t failed_count() const noexcept { return members.size() - finished_count(); }
};

// Runs one member per seed. A member that fails (any exception: runaway, refused time step, ...)
// is recorded with its message and does not stop the others. With options.run.write_files, also
// writes DIR/ensemble_summary.txt and .csv. The plots are the caller's (apps/ellc/dem_command.cpp).
[[nodiscard]] EnsembleResult run_ensemble(const Scenario& scenario, const std::vector<std::uint64_t>& seeds,
                                          const EnsembleOptions& options);

// ensemble_summary.txt: the members and their status (`seed_<s> = finished` or `= failed: ...`),
// then the statistics as a table. ensemble_summary.csv: quantity,n,mean,sd,standard_error,min,max.
void write_ensemble_summary_text(std::ostream& out, const EnsembleResult& result);
void write_ensemble_summary_csv(std::ostream& out, const EnsembleResult& result);
// Both files into result.directory; returns the path of the .txt.
std::string write_ensemble_summary(const EnsembleResult& result);

}  // namespace ellc::scenario
