#include "ellc/engine/cpu_load.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <fstream>
#include <iterator>
#include <mutex>

#if defined(__linux__)
#include <sched.h>
#include <unistd.h>
#endif

namespace ellc::engine {

namespace {

// The next whitespace-separated field of `text` from `at`, as an unsigned integer.
std::optional<unsigned long long> next_number(std::string_view text, std::size_t& at) noexcept {
  while (at < text.size() && (text[at] == ' ' || text[at] == '\t')) ++at;
  unsigned long long value = 0;
  const char* first = text.data() + at;
  const auto [end, error] = std::from_chars(first, text.data() + text.size(), value);
  if (error != std::errc{} || end == first) return std::nullopt;
  at += static_cast<std::size_t>(end - first);
  return value;
}

// Seconds on the steady clock: the wall time of a reading, and the clock sample() checks first.
double steady_seconds() noexcept {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// next_number() for a field that must end there (at whitespace or the end): "15x000" is no number.
std::optional<unsigned long long> whole_field(std::string_view text, std::size_t& at) noexcept {
  const auto value = next_number(text, at);
  if (!value || (at < text.size() && text[at] != ' ' && text[at] != '\t' && text[at] != '\n')) return std::nullopt;
  return value;
}

// quota / period in cores; nullopt unless both are positive (cgroup v1's −1 and v2's "max" are
// no number here, so no quota).
std::optional<double> quota_over_period(std::optional<unsigned long long> quota,
                                        std::optional<unsigned long long> period) noexcept {
  if (!quota || !period || *quota == 0 || *period == 0) return std::nullopt;
  return static_cast<double>(*quota) / static_cast<double>(*period);
}

std::optional<std::string> file_text(const std::string& path) noexcept {
  try {
    std::ifstream in(path);
    if (!in) return std::nullopt;
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  } catch (...) {  // noexcept API: an allocation failure reads as "no quota"
    return std::nullopt;
  }
}

}  // namespace

std::optional<double> quota_cores_v2(std::string_view cpu_max) noexcept {
  std::size_t at = 0;
  const auto quota = whole_field(cpu_max, at);  // evaluated in this order: quota, then period
  const auto period = quota ? whole_field(cpu_max, at) : std::nullopt;
  return quota_over_period(quota, period);
}

std::optional<double> quota_cores_v1(std::string_view quota_us, std::string_view period_us) noexcept {
  std::size_t quota_at = 0;
  std::size_t period_at = 0;
  return quota_over_period(whole_field(quota_us, quota_at), whole_field(period_us, period_at));
}

std::optional<double> cpu_quota_cores(std::string_view membership, const std::string& mount) noexcept {
  std::optional<double> tightest;
  const auto take = [&tightest](std::optional<double> quota) {
    if (quota && (!tightest || *quota < *tightest)) tightest = quota;
  };
  // From the cgroup's directory under `base` up to `base` itself.
  const auto walk_up = [](const std::string& base, std::string_view path, const auto& read_at) {
    std::string at(path);
    while (true) {
      read_at(at == "/" ? base : base + at);
      if (at.empty() || at == "/") return;
      const std::size_t slash = at.find_last_of('/');  // paths start with '/'
      at.erase(slash == 0 ? 1 : slash);
    }
  };
  try {
    std::size_t line_begin = 0;
    while (line_begin < membership.size()) {
      std::size_t line_end = membership.find('\n', line_begin);
      if (line_end == std::string_view::npos) line_end = membership.size();
      const std::string_view line = membership.substr(line_begin, line_end - line_begin);
      line_begin = line_end + 1;
      // "HIERARCHY-ID:CONTROLLERS:PATH"; v2's line is "0::PATH".
      const std::size_t first = line.find(':');
      const std::size_t second = first == std::string_view::npos ? first : line.find(':', first + 1);
      if (second == std::string_view::npos) continue;
      const std::string_view controllers = line.substr(first + 1, second - first - 1);
      const std::string_view path = line.substr(second + 1);
      if (path.empty() || path.front() != '/') continue;
      if (line.substr(0, first) == "0" && controllers.empty()) {
        walk_up(mount, path, [&](const std::string& dir) {
          if (const auto text = file_text(dir + "/cpu.max")) take(quota_cores_v2(*text));
        });
        continue;
      }
      bool has_cpu = false;  // "cpu" in the comma-separated list ("cpu,cpuacct" is mounted as such)
      for (std::size_t at = 0; at <= controllers.size();) {
        std::size_t comma = controllers.find(',', at);
        if (comma == std::string_view::npos) comma = controllers.size();
        has_cpu = has_cpu || controllers.substr(at, comma - at) == "cpu";
        at = comma + 1;
      }
      if (!has_cpu) continue;
      for (const std::string& base : {mount + "/" + std::string(controllers), mount + "/cpu"}) {
        walk_up(base, path, [&](const std::string& dir) {
          const auto quota = file_text(dir + "/cpu.cfs_quota_us");
          const auto period = file_text(dir + "/cpu.cfs_period_us");
          if (quota && period) take(quota_cores_v1(*quota, *period));
        });
      }
    }
  } catch (...) {  // string allocation: no quota known
    return tightest;
  }
  return tightest;
}

std::optional<double> process_cpu_quota() noexcept {
#if defined(__linux__)
  static const std::optional<double> quota = []() -> std::optional<double> {
    const auto membership = file_text("/proc/self/cgroup");
    if (!membership) return std::nullopt;
    return cpu_quota_cores(*membership, "/sys/fs/cgroup");
  }();
  return quota;
#else
  return std::nullopt;
#endif
}

int threads_within_quota(int threads, std::optional<double> quota_cores) noexcept {
  threads = std::max(threads, 1);
  if (!quota_cores || !(*quota_cores > 0.0)) return threads;
  const double cap = std::ceil(std::min(*quota_cores, 1e6));
  return std::min(threads, std::max(1, static_cast<int>(cap)));
}

std::optional<int> core_of(std::string_view line) noexcept {
  if (line.size() < 4 || line.substr(0, 3) != "cpu") return std::nullopt;
  int core = 0;
  const auto [end, error] = std::from_chars(line.data() + 3, line.data() + line.size(), core);
  if (error != std::errc{} || end == line.data() + 3 || core < 0) return std::nullopt;
  return core;
}

std::optional<double> busy_ticks(std::string_view line) noexcept {
  if (line.substr(0, 3) != "cpu") return std::nullopt;
  std::size_t at = line.find_first_of(" \t");
  if (at == std::string_view::npos) return std::nullopt;
  // user nice system idle iowait irq softirq: seven fields at least (Linux ≥ 2.6).
  std::array<unsigned long long, 7> field{};
  for (auto& value : field) {
    const auto number = next_number(line, at);
    if (!number) return std::nullopt;
    value = *number;
  }
  return static_cast<double>(field[0] + field[1] + field[2] + field[5] + field[6]);
}

double other_busy_cores(const CpuTimes& before, const CpuTimes& after) noexcept {
  const double wall = after.wall - before.wall;
  if (!(wall > 0.0)) return 0.0;
  const double others = ((after.busy - before.busy) - (after.own - before.own)) / wall;
  return std::clamp(others, 0.0, static_cast<double>(after.cores));
}

std::optional<CpuTimes> read_cpu_times() noexcept {
#if defined(__linux__)
  cpu_set_t allowed;
  CPU_ZERO(&allowed);
  if (sched_getaffinity(0, sizeof allowed, &allowed) != 0) return std::nullopt;
  const long ticks_per_second = sysconf(_SC_CLK_TCK);
  if (ticks_per_second <= 0) return std::nullopt;
  timespec own{};
  if (clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &own) != 0) return std::nullopt;
  std::FILE* file = std::fopen("/proc/stat", "r");
  if (file == nullptr) return std::nullopt;
  CpuTimes times;
  std::array<char, 512> buffer{};
  while (std::fgets(buffer.data(), static_cast<int>(buffer.size()), file) != nullptr) {
    const std::string_view line(buffer.data(), std::strlen(buffer.data()));
    if (line.substr(0, 3) != "cpu") break;  // the cpu lines come first
    const auto core = core_of(line);
    if (!core || *core >= CPU_SETSIZE || !CPU_ISSET(*core, &allowed)) continue;
    const auto ticks = busy_ticks(line);
    if (!ticks) continue;
    times.busy += *ticks / static_cast<double>(ticks_per_second);
    ++times.cores;
  }
  std::fclose(file);
  if (times.cores == 0) return std::nullopt;
  times.own = static_cast<double>(own.tv_sec) + 1e-9 * static_cast<double>(own.tv_nsec);
  times.wall = steady_seconds();
  return times;
#else
  return std::nullopt;
#endif
}

std::optional<OtherProcessesLoad::Reading> OtherProcessesLoad::sample(double min_interval) noexcept {
  if (!readable_) return std::nullopt;
  if (last_) {  // the clock first: /proc/stat is read only when an answer is due
    if (steady_seconds() - last_->wall < min_interval) return std::nullopt;
  }
  const std::optional<CpuTimes> now = read_cpu_times();
  if (!now) {
    readable_ = false;
    return std::nullopt;
  }
  std::optional<Reading> reading;
  if (last_ && last_->cores == now->cores) reading = Reading{other_busy_cores(*last_, *now), now->cores};
  last_ = now;
  return reading;
}

std::optional<OtherProcessesLoad::Reading> process_other_load(double min_interval) noexcept {
  static std::mutex mutex;
  static OtherProcessesLoad load;
  static std::optional<OtherProcessesLoad::Reading> latest;
  const std::lock_guard lock(mutex);
  if (const auto reading = load.sample(min_interval)) latest = reading;
  return latest;
}

}  // namespace ellc::engine
