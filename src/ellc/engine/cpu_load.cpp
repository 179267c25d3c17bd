#include "ellc/engine/cpu_load.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <ctime>
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

}  // namespace

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
