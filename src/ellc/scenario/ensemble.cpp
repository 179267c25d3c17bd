#include "ellc/scenario/ensemble.hpp"

#include <algorithm>
#include <atomic>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <unordered_map>

#include "ellc/io/input_error.hpp"

namespace ellc::scenario {

namespace {

std::string seed_list_text(const std::vector<long>& seeds) {
  std::string text = "[";
  for (std::size_t i = 0; i < seeds.size(); ++i) text += (i ? ", " : "") + std::to_string(seeds[i]);
  return text + "]";
}

std::string trimmed(std::string_view text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const auto last = text.find_last_not_of(" \t\r");
  return std::string(text.substr(first, last - first + 1));
}

// The whole of `text` as a number, or nullopt (true, false, words, "12 um").
std::optional<double> as_number(const std::string& text) {
  if (text.empty()) return std::nullopt;
  const char* begin = text.data();
  const char* end = begin + text.size();
  if (*begin == '+') ++begin;  // from_chars refuses a leading +
  double value = 0.0;
  const auto [stop, error] = std::from_chars(begin, end, value);
  if (error != std::errc{} || stop != end) return std::nullopt;
  return value;
}

std::string one_line(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  return text;
}

std::string number_text(double value) {
  char text[40];
  std::snprintf(text, sizeof text, "%.10g", value);
  return text;
}

}  // namespace

std::vector<std::uint64_t> read_packing_seeds(TableReader& packing) {
  const auto seeds = packing.optional_integers("seeds", 0);
  if (!seeds) return {};
  const std::string expected = "a list of 1 to " + std::to_string(kMaxEnsembleMembers) +
                               " different packing seeds, integers >= 0 (one run each)";
  if (seeds->empty() || seeds->size() > kMaxEnsembleMembers)
    packing.fail("seeds", "a list of " + std::to_string(seeds->size()) + " seeds", expected);
  for (std::size_t i = 0; i < seeds->size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if ((*seeds)[i] == (*seeds)[j])
        packing.fail("seeds", seed_list_text(*seeds),
                     expected + "; " + std::to_string((*seeds)[i]) + " is both packing.seeds[" + std::to_string(j) +
                         "] and packing.seeds[" + std::to_string(i) + "]");
  if (packing.has("seed"))
    packing.fail("seeds", seed_list_text(*seeds),
                 "packing.seed or packing.seeds, not both (seeds runs one member per seed; remove seed)");
  return {seeds->begin(), seeds->end()};
}

std::vector<std::uint64_t> ensemble_seeds(const Scenario& scenario, std::optional<long long> count) {
  if (!count) return scenario.seeds;
  if (!scenario.seeds.empty())
    throw InputError("", "--seeds", std::to_string(*count),
                     "no --seeds, since " + scenario.source + " lists packing.seeds (" +
                         std::to_string(scenario.seeds.size()) + " seeds); give one of the two");
  if (*count < 1 || *count > static_cast<long long>(kMaxEnsembleMembers))
    throw InputError("", "--seeds", std::to_string(*count),
                     "a number of packing seeds, an integer in [1, " + std::to_string(kMaxEnsembleMembers) + "]");
  std::vector<std::uint64_t> seeds;
  for (long long k = 0; k < *count; ++k) seeds.push_back(scenario.packing.seed + static_cast<std::uint64_t>(k));
  return seeds;
}

std::string member_directory(const std::string& ensemble_directory, std::uint64_t seed) {
  return (std::filesystem::path(ensemble_directory) / ("seed_" + std::to_string(seed))).string();
}

std::vector<FigureStatistics> summary_statistics(const std::vector<std::string>& summary_texts) {
  std::vector<std::string> order;
  std::unordered_map<std::string, std::vector<double>> values;
  std::unordered_map<std::string, bool> numeric;  // a key counts once it has a number in some member
  for (const std::string& text : summary_texts) {
    std::istringstream lines(text);
    std::string line;
    while (std::getline(lines, line)) {
      const std::string content = trimmed(line);
      if (content.empty() || content[0] == '#') continue;
      const auto equals = content.find('=');
      if (equals == std::string::npos) continue;
      const std::string key = trimmed(std::string_view(content).substr(0, equals));
      const auto value = as_number(trimmed(std::string_view(content).substr(equals + 1)));
      if (key.empty() || !value) continue;
      if (!numeric[key]) {
        numeric[key] = true;
        order.push_back(key);
      }
      if (std::isfinite(*value)) values[key].push_back(*value);
    }
  }
  std::vector<FigureStatistics> statistics;
  for (const std::string& key : order) {
    const std::vector<double>& x = values[key];
    FigureStatistics figure;
    figure.name = key;
    figure.count = x.size();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    if (x.empty()) {
      figure.mean = figure.sd = figure.standard_error = figure.min = figure.max = nan;
    } else {
      const double n = static_cast<double>(x.size());
      double sum = 0.0;
      for (double v : x) sum += v;
      figure.mean = sum / n;
      double squares = 0.0;
      for (double v : x) squares += (v - figure.mean) * (v - figure.mean);
      figure.sd = x.size() > 1 ? std::sqrt(squares / (n - 1.0)) : nan;
      figure.standard_error = figure.sd / std::sqrt(n);
      figure.min = *std::min_element(x.begin(), x.end());
      figure.max = *std::max_element(x.begin(), x.end());
    }
    statistics.push_back(figure);
  }
  return statistics;
}

std::size_t EnsembleResult::finished_count() const noexcept {
  return static_cast<std::size_t>(
      std::count_if(members.begin(), members.end(), [](const EnsembleMember& m) { return m.finished; }));
}

namespace {

// One member: the scenario with its seed, run to the end of the protocol. Every failure is caught
// and recorded in the member (on_member_start and on_member_end are outside: they must not throw).
class MemberRun {
 public:
  MemberRun(const Scenario& scenario, const EnsembleOptions& options, const std::string& directory, bool one_thread,
            std::mutex& lock)
      : scenario_(scenario), options_(options), directory_(directory), one_thread_(one_thread), lock_(lock) {}

  void run(EnsembleMember& member) const {
    const auto start = std::chrono::steady_clock::now();
    Scenario scenario = scenario_;
    scenario.packing.seed = member.seed;
    scenario.seeds.clear();
    RunOptions run = options_.run;
    if (run.write_files) member.directory = run.output_directory = member_directory(directory_, member.seed);
    if (one_thread_) run.parallel_threshold = std::numeric_limits<std::size_t>::max();
    if (options_.on_member_start) {
      std::lock_guard<std::mutex> guard(lock_);
      options_.on_member_start(member);
    }
    std::unique_ptr<ScenarioRunner> runner;
    try {
      runner = std::make_unique<ScenarioRunner>(std::move(scenario), run);
      member.warnings = runner->warnings();
      const std::uint64_t chunk = std::max<std::uint64_t>(options_.steps_per_progress, 1);
      while (!runner->done()) {
        runner->advance(chunk);
        if (options_.on_progress) {
          std::lock_guard<std::mutex> guard(lock_);
          options_.on_progress(member, *runner);
        }
      }
      if (run.write_files) (void)runner->write_summary();
      member.summary = runner->summary();
      std::ostringstream text;
      write_summary_lines(text, scenario_.source, member.summary);
      member.summary_text = text.str();
      member.finished = member.summary.finished;
      if (!member.finished) member.error = "the protocol did not reach its end (summary: finished = false)";
    } catch (const std::exception& error) {
      member.error = one_line(error.what());
    } catch (...) {
      member.error = "an unknown error";
    }
    member.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (options_.on_member_end) {
      std::lock_guard<std::mutex> guard(lock_);
      options_.on_member_end(member, runner.get());
    }
  }

 private:
  const Scenario& scenario_;
  const EnsembleOptions& options_;
  const std::string& directory_;
  bool one_thread_;
  std::mutex& lock_;
};

}  // namespace

EnsembleResult run_ensemble(const Scenario& scenario, const std::vector<std::uint64_t>& seeds,
                            const EnsembleOptions& options) {
  EnsembleResult result;
  result.source = scenario.source;
  result.directory = options.run.output_directory.empty() ? scenario.output.directory : options.run.output_directory;
  if (!options.run.restart_path.empty())
    throw InputError("", "--restart", options.run.restart_path,
                     "no --restart for an ensemble: continue one member on its own, with -o DIR/seed_<s> "
                     "--restart DIR/seed_<s>/checkpoint.bin");
  result.members.resize(seeds.size());
  for (std::size_t i = 0; i < seeds.size(); ++i) {
    result.members[i].index = i;
    result.members[i].seed = seeds[i];
  }
  if (options.run.write_files) std::filesystem::create_directories(result.directory);

  const std::size_t workers = std::clamp<std::size_t>(static_cast<std::size_t>(std::max(options.jobs, 1)), 1,
                                                      std::max<std::size_t>(seeds.size(), 1));
  std::mutex lock;
  const MemberRun member_run(scenario, options, result.directory, workers > 1, lock);
  std::atomic<std::size_t> next{0};
  std::exception_ptr escaped;  // from a callback: rethrown once every worker has stopped
  const auto work = [&] {
    try {
      for (std::size_t i = next++; i < result.members.size(); i = next++) member_run.run(result.members[i]);
    } catch (...) {
      std::lock_guard<std::mutex> guard(lock);
      if (!escaped) escaped = std::current_exception();
      next = result.members.size();
    }
  };
  if (workers == 1) {
    work();  // on the caller's thread, with its OpenMP threads
  } else {
    std::vector<std::thread> pool;
    for (std::size_t w = 0; w < workers; ++w) pool.emplace_back(work);
    for (auto& thread : pool) thread.join();
  }
  if (escaped) std::rethrow_exception(escaped);

  std::vector<std::string> texts;
  for (const EnsembleMember& member : result.members)
    if (member.finished) texts.push_back(member.summary_text);
  result.statistics = summary_statistics(texts);
  if (options.run.write_files) (void)write_ensemble_summary(result);
  return result;
}

void write_ensemble_summary_text(std::ostream& out, const EnsembleResult& result) {
  const std::size_t finished = result.finished_count();
  out << "# ellc dem ensemble summary: " << result.source << "\n"
      << "# one run per packing seed, each with its outputs in seed_<seed>/ (docs/engine.md, \"Ensembles over "
         "packing seeds\")\n"
      << "members = " << result.members.size() << "\nfinished = " << finished << "\nfailed = " << result.failed_count()
      << "\nseeds =";
  for (const EnsembleMember& member : result.members) out << ' ' << member.seed;
  out << "\n";
  for (const EnsembleMember& member : result.members) {
    out << "seed_" << member.seed << " = ";
    if (member.finished)
      out << "finished\n";
    else
      out << "failed: " << member.error << "\n";
  }
  out << "\n# statistics over the " << finished << " finished members. n: the members with a finite value;\n"
      << "# sd: sample standard deviation sqrt(sum (x - mean)^2 / (n - 1)), nan for n = 1; "
         "standard_error: sd / sqrt(n)\n";
  std::size_t width = 8;
  for (const FigureStatistics& figure : result.statistics) width = std::max(width, figure.name.size());
  char line[512];
  std::snprintf(line, sizeof line, "# %-*s %5s %16s %16s %16s %16s %16s\n", static_cast<int>(width - 2), "quantity",
                "n", "mean", "sd", "standard_error", "min", "max");
  out << line;
  if (result.statistics.empty()) out << "# (none: no member finished)\n";
  for (const FigureStatistics& f : result.statistics) {
    std::snprintf(line, sizeof line, "%-*s %5zu %16.10g %16.10g %16.10g %16.10g %16.10g\n", static_cast<int>(width),
                  f.name.c_str(), f.count, f.mean, f.sd, f.standard_error, f.min, f.max);
    out << line;
  }
}

void write_ensemble_summary_csv(std::ostream& out, const EnsembleResult& result) {
  out << "quantity,n,mean,sd,standard_error,min,max\n";
  for (const FigureStatistics& f : result.statistics)
    out << f.name << ',' << f.count << ',' << number_text(f.mean) << ',' << number_text(f.sd) << ','
        << number_text(f.standard_error) << ',' << number_text(f.min) << ',' << number_text(f.max) << '\n';
}

std::string write_ensemble_summary(const EnsembleResult& result) {
  std::filesystem::create_directories(result.directory);
  const auto directory = std::filesystem::path(result.directory);
  std::string text_path = (directory / "ensemble_summary.txt").string();
  const std::string csv_path = (directory / "ensemble_summary.csv").string();
  std::ofstream text(text_path);
  write_ensemble_summary_text(text, result);
  std::ofstream csv(csv_path);
  write_ensemble_summary_csv(csv, result);
  if (!text || !csv) throw std::runtime_error("cannot write " + text_path + " and " + csv_path);
  return text_path;
}

}  // namespace ellc::scenario
