// What other processes keep busy of our cores (engine/cpu_load.hpp): the parsing of /proc/stat,
// the arithmetic, the room rule, and on Linux a live reading while a child process spins; and the
// CPU quota: cgroup v1 and v2 files, the walk up a fake cgroup tree, the thread cap.

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>

#include "ellc/engine/cpu_load.hpp"

#if defined(__linux__)
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>
#endif

namespace ellc::engine {
namespace {

TEST(CpuLoad, BusyTicksAreUserNiceSystemIrqSoftirq) {
  // user nice system idle iowait irq softirq steal guest guest_nice
  const auto ticks = busy_ticks("cpu1 2191078 215958 156119 1003140 5631 7 1198 1780 0 0\n");
  ASSERT_TRUE(ticks.has_value());
  EXPECT_EQ(*ticks, 2191078.0 + 215958.0 + 156119.0 + 7.0 + 1198.0);
  EXPECT_TRUE(busy_ticks("cpu  4104713 422302 291326 2313549 8023 0 1378 3567 0 0").has_value());
  EXPECT_FALSE(busy_ticks("cpu0 1 2 3").has_value()) << "fewer than seven fields";
  EXPECT_FALSE(busy_ticks("intr 21077201 0 0 0 0 0 0 0").has_value());
  EXPECT_FALSE(busy_ticks("cpu0 1 2 x 4 5 6 7").has_value());
}

TEST(CpuLoad, CoreNumbersOfThePerCoreLinesOnly) {
  EXPECT_EQ(core_of("cpu0 1 2 3 4 5 6 7"), 0);
  EXPECT_EQ(core_of("cpu17 1 2 3 4 5 6 7"), 17);
  EXPECT_FALSE(core_of("cpu  1 2 3 4 5 6 7").has_value()) << "the summary line";
  EXPECT_FALSE(core_of("ctxt 12345").has_value());
}

TEST(CpuLoad, OthersAreTheBusyTimeLessOurOwnPerWallSecond) {
  const CpuTimes before{10.0, 3.0, 100.0, 2};
  EXPECT_DOUBLE_EQ(other_busy_cores(before, {11.5, 3.9, 101.0, 2}), 0.6);  // 1.5 busy, 0.9 ours
  EXPECT_DOUBLE_EQ(other_busy_cores(before, {10.5, 3.9, 101.0, 2}), 0.0) << "clamped at 0 (tick rounding)";
  EXPECT_DOUBLE_EQ(other_busy_cores(before, {19.0, 3.0, 101.0, 2}), 2.0) << "clamped at the cores watched";
  EXPECT_DOUBLE_EQ(other_busy_cores(before, before), 0.0) << "no wall time";
}

// More than one thread only where one and a half cores are free: on two cores, others may keep
// at most half a core busy; on many cores, a little load elsewhere leaves the choice to timing.
TEST(CpuLoad, RoomForMoreThanOneThreadNeedsOneAndAHalfFreeCores) {
  EXPECT_TRUE(room_for_more_than_one(0.0, 2));
  EXPECT_TRUE(room_for_more_than_one(0.5, 2));
  EXPECT_FALSE(room_for_more_than_one(0.6, 2));
  EXPECT_FALSE(room_for_more_than_one(1.0, 2)) << "one core of two kept busy: issue 16's case";
  EXPECT_TRUE(room_for_more_than_one(2.0, 64)) << "64 cores, 2 busy: 62 threads still run unshared";
  EXPECT_FALSE(room_for_more_than_one(3.0, 4)) << "one free core of four";
  EXPECT_FALSE(room_for_more_than_one(0.0, 1)) << "a process allowed one core";
}

TEST(CpuLoad, QuotaInCoresFromCgroupFiles) {
  EXPECT_EQ(quota_cores_v2("150000 100000\n"), 1.5);
  EXPECT_EQ(quota_cores_v2("200000 100000"), 2.0);
  EXPECT_FALSE(quota_cores_v2("max 100000\n").has_value()) << "no limit";
  EXPECT_FALSE(quota_cores_v2("").has_value());
  EXPECT_FALSE(quota_cores_v2("150000").has_value()) << "no period";
  EXPECT_FALSE(quota_cores_v2("150000 0").has_value());
  EXPECT_FALSE(quota_cores_v2("15x000 100000").has_value());
  EXPECT_EQ(quota_cores_v1("50000\n", "100000\n"), 0.5);
  EXPECT_FALSE(quota_cores_v1("-1\n", "100000\n").has_value()) << "cgroup v1's no limit";
  EXPECT_FALSE(quota_cores_v1("", "100000").has_value());
}

TEST(CpuLoad, ThreadsAreCappedAtTheQuotaRoundedUp) {
  EXPECT_EQ(threads_within_quota(64, 2.0), 2) << "a 2-core limit on a 64-core node";
  EXPECT_EQ(threads_within_quota(64, 1.5), 2);
  EXPECT_EQ(threads_within_quota(64, 0.25), 1);
  EXPECT_EQ(threads_within_quota(2, 8.0), 2) << "a quota above the cores changes nothing";
  EXPECT_EQ(threads_within_quota(4, std::nullopt), 4);
  EXPECT_EQ(threads_within_quota(0, std::nullopt), 1);
  EXPECT_EQ(threads_within_quota(8, 1e300), 8);
}

// A cgroup tree in a temporary directory: the tightest limit on the path up to the mount binds.
class CpuQuotaTree : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = std::filesystem::temp_directory_path() /
            ("ellc_cpu_quota_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(root_);
  }
  void TearDown() override { std::filesystem::remove_all(root_); }
  void write(const std::string& relative, const std::string& text) const {
    const auto path = root_ / relative;
    std::filesystem::create_directories(path.parent_path());
    std::ofstream(path) << text;
  }
  [[nodiscard]] std::string mount() const { return root_.string(); }

  std::filesystem::path root_;
};

TEST_F(CpuQuotaTree, CgroupV2TakesTheTightestLimitUpTheTree) {
  write("kubepods/pod1/cpu.max", "300000 100000\n");
  write("kubepods/pod1/app/cpu.max", "max 100000\n");
  write("kubepods/cpu.max", "max 100000\n");
  EXPECT_EQ(cpu_quota_cores("0::/kubepods/pod1/app\n", mount()), 3.0) << "the pod's limit binds the app";
  write("kubepods/pod1/app/cpu.max", "120000 100000\n");
  EXPECT_EQ(cpu_quota_cores("0::/kubepods/pod1/app\n", mount()), 1.2);
  EXPECT_FALSE(cpu_quota_cores("0::/kubepods\n", mount()).has_value());
}

TEST_F(CpuQuotaTree, AContainerSeeingItsOwnCgroupAsTheRoot) {
  write("cpu.max", "100000 100000\n");  // the namespaced root holds the container's limit
  EXPECT_EQ(cpu_quota_cores("0::/\n", mount()), 1.0);
  EXPECT_EQ(cpu_quota_cores("0::/docker/abc\n", mount()), 1.0) << "a host path not under the mount";
}

TEST_F(CpuQuotaTree, CgroupV1CpuControllerUnderEitherMountName) {
  write("cpu,cpuacct/batch/cpu.cfs_quota_us", "150000\n");
  write("cpu,cpuacct/batch/cpu.cfs_period_us", "100000\n");
  const std::string membership = "12:memory:/batch\n4:cpu,cpuacct:/batch/job\n1:name=systemd:/batch\n";
  EXPECT_EQ(cpu_quota_cores(membership, mount()), 1.5);
  write("cpu/batch/job/cpu.cfs_quota_us", "-1\n");
  write("cpu/batch/job/cpu.cfs_period_us", "100000\n");
  write("cpu/batch/cpu.cfs_quota_us", "50000\n");
  write("cpu/batch/cpu.cfs_period_us", "100000\n");
  EXPECT_EQ(cpu_quota_cores(membership, mount()), 0.5);
  EXPECT_FALSE(cpu_quota_cores("4:cpuacct:/batch\n", mount()).has_value()) << "not the cpu controller";
}

TEST_F(CpuQuotaTree, NoFilesOrNoMembershipMeanNoQuota) {
  EXPECT_FALSE(cpu_quota_cores("0::/a/b\n", mount()).has_value());
  EXPECT_FALSE(cpu_quota_cores("", mount()).has_value());
  EXPECT_FALSE(cpu_quota_cores("garbage without colons\n0:x\n", mount()).has_value());
}

#if defined(__linux__)
// A child process that spins for the reading's window shows up as at least half a core kept busy
// by others (the child alone, whatever else the machine runs, counts for its whole share).
TEST(CpuLoad, ASpinningChildIsSeenAsAnotherProcess) {
  OtherProcessesLoad load;
  ASSERT_FALSE(load.sample(0.0).has_value()) << "the first call only takes the first reading";
  if (!read_cpu_times()) GTEST_SKIP() << "/proc/stat not readable here";
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    volatile unsigned long spin = 0;
    while (std::chrono::steady_clock::now() < until) spin = spin + 1;
    _exit(0);
  }
  const auto start = std::chrono::steady_clock::now();
  while (std::chrono::steady_clock::now() - start < std::chrono::milliseconds(400)) {
    // sleeps, so that this process's own time stays small beside the child's
    timespec pause{0, 20'000'000};
    nanosleep(&pause, nullptr);
  }
  const auto reading = load.sample(0.0);
  kill(child, SIGKILL);
  waitpid(child, nullptr, 0);
  ASSERT_TRUE(reading.has_value());
  EXPECT_GE(reading->cores, 1);
  EXPECT_GE(reading->others_busy, 0.5);
}

// The process's reading: after its first call it answers, and keeps its latest answer between
// renewals (a simulation built later in the process finds it at once).
TEST(CpuLoad, TheProcessReadingAnswersAfterItsFirstCall) {
  if (!read_cpu_times()) GTEST_SKIP() << "/proc/stat not readable here";
  (void)process_other_load(0.0);
  const auto first = process_other_load(0.0);
  ASSERT_TRUE(first.has_value());
  const auto kept = process_other_load(3600.0);  // not renewed: the latest answer
  ASSERT_TRUE(kept.has_value());
  EXPECT_EQ(kept->others_busy, first->others_busy);
}

TEST(CpuLoad, NoAnswerBeforeTheInterval) {
  OtherProcessesLoad load;
  (void)load.sample();
  EXPECT_FALSE(load.sample(10.0).has_value());
}
#endif

}  // namespace
}  // namespace ellc::engine
