#pragma once
// How much of the cores this process may run on other processes keep busy: what the adaptive
// thread count (thread_count.hpp) needs to know before it tries more than one thread. Two threads whose
// cores are shared with a busy process wait at every barrier for the one that is descheduled
// (issue 16); timing them to find out costs steps, reading the kernel's counters costs nothing.
//
// Linux: the per-core lines of /proc/stat for the cores in this process's affinity mask (not the
// whole machine's line: in a container that line counts cores we cannot run on), less this
// process's own CPU time. Elsewhere, or when /proc/stat cannot be read: unknown (std::nullopt),
// and the thread count goes by step times alone, as before.

#include <optional>
#include <string>
#include <string_view>

namespace ellc::engine {

// Cumulative CPU seconds at one moment.
struct CpuTimes {
  double busy = 0.0;  // user + nice + system + irq + softirq of the cores we may run on
  double own = 0.0;   // this process, all threads (CLOCK_PROCESS_CPUTIME_ID)
  double wall = 0.0;  // steady clock
  int cores = 0;      // how many cores `busy` covers
};

// Busy ticks of one line of /proc/stat, "cpuN user nice system idle iowait irq softirq steal ...":
// user + nice + system + irq + softirq (idle, iowait and steal are not another process of ours to
// share a core with; guest time is inside user). nullopt when the line is not such a line.
[[nodiscard]] std::optional<double> busy_ticks(std::string_view proc_stat_line) noexcept;

// The core number N of a line "cpuN ..." (nullopt for the summary line "cpu " and other lines).
[[nodiscard]] std::optional<int> core_of(std::string_view proc_stat_line) noexcept;

// Now's counters; nullopt off Linux or when /proc/stat or the affinity mask cannot be read.
[[nodiscard]] std::optional<CpuTimes> read_cpu_times() noexcept;

// Cores kept busy by other processes between two readings, (Δbusy − Δown)/Δwall, clamped to
// [0, cores]; 0 when no wall time passed.
[[nodiscard]] double other_busy_cores(const CpuTimes& before, const CpuTimes& after) noexcept;

// Whether more than one thread can help: others leave at least one and a half of the `cores`
// free. Below that, every thread beyond the first shares the one free core (or less) and waits
// at each barrier for its turn (issue 16: two threads 5× slower than one with one core of two
// busy). Above it the step times decide: 64 threads with 2 of 64 cores busy still beat one
// thread by far, and only a measurement tells how far.
// `cores`: those of the affinity mask, or fewer under a CPU quota (cpu_quota_cores below).
[[nodiscard]] constexpr bool room_for_more_than_one(double others_busy, double cores) noexcept {
  return cores - others_busy >= 1.5;
}

// A CPU quota (a container's `--cpus`, a Kubernetes CPU limit, systemd's CPUQuota) caps the CPU
// time a process may use per wall second, whatever its affinity mask: libgomp still starts a
// thread per core of the mask, and threads beyond the quota use it up early in each period and
// then all wait, throttled, for the next (a 2-core quota on a 64-core node: 64 threads run for
// ~3 ms of every 100). The cores it may not use look idle in /proc/stat. So the thread count
// reads the quota too.
//
// The quota in cores of a cgroup v2 `cpu.max` ("QUOTA PERIOD" in µs; "max PERIOD": none, nullopt).
[[nodiscard]] std::optional<double> quota_cores_v2(std::string_view cpu_max) noexcept;
// The same from cgroup v1's `cpu.cfs_quota_us` (−1: none) and `cpu.cfs_period_us`.
[[nodiscard]] std::optional<double> quota_cores_v1(std::string_view quota_us, std::string_view period_us) noexcept;

// The tightest quota over this process's cgroup and its ancestors (a limit on a parent binds its
// children), v2 and v1 alike, from `membership` (the text of /proc/self/cgroup) and the cgroup
// file system mounted at `mount`. Where the process's path is not found under the mount (a
// container that sees its own cgroup as the root), the walk up still reaches the mount's own
// files. nullopt when no quota is set or nothing can be read.
[[nodiscard]] std::optional<double> cpu_quota_cores(std::string_view membership, const std::string& mount) noexcept;

// The process's quota (/proc/self/cgroup, /sys/fs/cgroup), read once: quotas are set when a
// container starts. nullopt off Linux.
[[nodiscard]] std::optional<double> process_cpu_quota() noexcept;

// At most as many threads as the quota has cores, rounded up (a 1.5-core quota still gains from
// a second thread), and at least one; `threads` itself without a quota.
[[nodiscard]] int threads_within_quota(int threads, std::optional<double> quota_cores) noexcept;

// Successive readings; sample() answers for the time since the last answer.
class OtherProcessesLoad {
 public:
  // The cores other processes kept busy since the last answer, and how many cores were watched,
  // once `min_interval` seconds have passed since it (the kernel's counters tick at 100 Hz, so a
  // shorter window would be mostly rounding); nullopt before that, or when unknown.
  struct Reading {
    double others_busy = 0.0;
    int cores = 0;
  };
  [[nodiscard]] std::optional<Reading> sample(double min_interval = 0.1) noexcept;

 private:
  std::optional<CpuTimes> last_;
  bool readable_ = true;  // false after a failed read: not tried again
};

// One reading for the whole process (the load is the machine's, not a simulation's): the latest
// answer of a process-wide OtherProcessesLoad, refreshed when `min_interval` has passed since it;
// the first call starts it and answers nullopt. So a simulation built late in a process (a
// benchmark's timed one, an ensemble's next member) knows the load before its first step.
// Thread-safe.
[[nodiscard]] std::optional<OtherProcessesLoad::Reading> process_other_load(double min_interval = 0.05) noexcept;

}  // namespace ellc::engine
