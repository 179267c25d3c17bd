// The adaptive thread count (engine/thread_count.hpp) fed with synthetic step times: it settles
// on the faster count, follows a change of load, and spends little time probing the slower one.

#include <gtest/gtest.h>

#include "ellc/engine/thread_count.hpp"

namespace ellc::engine {
namespace {

// Runs `steps` steps whose time is `seconds(threads)`; returns the steps spent on each count.
template <typename Time>
std::pair<int, int> run(AdaptiveThreadCount& choice, int steps, Time seconds) {
  int on_one = 0, on_most = 0;
  for (int step = 0; step < steps; ++step) {
    const int threads = choice.current();
    (threads == 1 ? on_one : on_most) += 1;
    choice.record(seconds(threads));
  }
  return {on_one, on_most};
}

TEST(EngineThreadCount, KeepsAllThreadsWhenTheyAreFaster) {
  AdaptiveThreadCount choice(2);
  EXPECT_EQ(choice.current(), 2);
  const auto [on_one, on_two] = run(choice, 5000, [](int threads) { return threads == 2 ? 1.0 : 1.8; });
  EXPECT_EQ(choice.current(), 2);
  EXPECT_LT(on_one, 5000 / 50) << "probing one thread cost more than 2 % of the steps";
  EXPECT_GT(on_two, 0);
}

// A busy core: two threads 5× slower than one (issue 16's measurement).
TEST(EngineThreadCount, FallsBackToOneThreadWhenACoreIsBusy) {
  AdaptiveThreadCount choice(2);
  const auto [on_one, on_two] = run(choice, 5000, [](int threads) { return threads == 2 ? 5.0 : 1.0; });
  EXPECT_EQ(choice.current(), 1);
  // Total time against always one thread: the probes of two threads add at most a few per cent.
  const double total = on_one * 1.0 + on_two * 5.0;
  EXPECT_LT(total, 1.10 * 5000.0);
}

// Probing costs at most about kProbeBudget over a long run, also with a 5× slower count, and a
// losing probe stops after its first timed step.
TEST(EngineThreadCount, ProbingCostsAboutOnePerCentOverALongRun) {
  for (const double slower : {1.8, 5.0, 20.0}) {
    AdaptiveThreadCount choice(2);
    run(choice, 1000, [&](int threads) { return threads == 2 ? slower : 1.0; });  // settle first
    const auto [on_one, on_two] = run(choice, 20000, [&](int threads) { return threads == 2 ? slower : 1.0; });
    const double total = on_one * 1.0 + on_two * slower;
    EXPECT_LT(total, 1.015 * 20000.0) << "two threads " << slower << "x slower";
    EXPECT_LE(on_two, 2 * (20000 / 1024 + 1)) << "a probe ran more than two steps";
  }
}

// What a benchmark sees: 300 steps after the first 100, with a busy core (two threads 5× slower)
// and on a quiet machine (one thread 1.8× slower). Before probes were cut short and spaced by
// their cost, one probe of four steps fell into such a window and cost 3-5 % with a busy core.
TEST(EngineThreadCount, AWindowAfterTheStartPaysLittleForProbing) {
  {
    AdaptiveThreadCount choice(2);
    const auto busy = [](int threads) { return threads == 2 ? 5.0 : 1.0; };
    run(choice, 100, busy);
    const auto [on_one, on_two] = run(choice, 300, busy);
    EXPECT_LT(on_one * 1.0 + on_two * 5.0, 1.01 * 300.0);
  }
  {
    AdaptiveThreadCount choice(2);
    const auto quiet = [](int threads) { return threads == 2 ? 1.0 : 1.8; };
    run(choice, 100, quiet);
    const auto [on_one, on_two] = run(choice, 300, quiet);
    EXPECT_LT(on_one * 1.8 + on_two * 1.0, 1.01 * 300.0);
  }
}

TEST(EngineThreadCount, FollowsTheLoadBothWays) {
  AdaptiveThreadCount choice(2);
  run(choice, 2000, [](int threads) { return threads == 2 ? 1.0 : 1.9; });  // quiet
  EXPECT_EQ(choice.current(), 2);
  run(choice, 3000, [](int threads) { return threads == 2 ? 10.0 : 2.0; });  // another process arrives
  EXPECT_EQ(choice.current(), 1);
  run(choice, 3000, [](int threads) { return threads == 2 ? 1.0 : 1.9; });  // and leaves
  EXPECT_EQ(choice.current(), 2);
}

// Told that other processes leave no room (engine/cpu_load.hpp), it leaves all threads at once and
// never tries them, even where the step times alone would (here all threads look faster).
TEST(EngineThreadCount, WithoutRoomNeverRunsAllThreads) {
  AdaptiveThreadCount choice(2);
  EXPECT_EQ(choice.current(), 2);
  choice.set_room_for_more(false);
  EXPECT_EQ(choice.current(), 1);
  const auto [on_one, on_two] = run(choice, 5000, [](int threads) { return threads == 2 ? 1.0 : 1.8; });
  EXPECT_EQ(on_two, 0);
  EXPECT_EQ(on_one, 5000);
}

// Room returns: all threads are probed as soon as one thread's first window is measured, and kept.
TEST(EngineThreadCount, WhenRoomReturnsAllThreadsAreTriedAtOnce) {
  AdaptiveThreadCount choice(2);
  const auto quiet = [](int threads) { return threads == 2 ? 1.0 : 1.8; };
  choice.set_room_for_more(false);
  run(choice, 3000, quiet);  // long enough for the probe interval to have grown, had it probed
  choice.set_room_for_more(true);
  const auto [on_one, on_two] = run(choice, AdaptiveThreadCount::kWindow + AdaptiveThreadCount::kProbeSteps, quiet);
  EXPECT_EQ(choice.current(), 2);
  EXPECT_LE(on_one, AdaptiveThreadCount::kWindow);
  EXPECT_GT(on_two, 0);
}

// Room gone in the middle of a probe of one thread against all: it settles on one thread.
TEST(EngineThreadCount, RoomGoneDuringAProbeSettlesOnOneThread) {
  AdaptiveThreadCount choice(2);
  const auto quiet = [](int threads) { return threads == 2 ? 1.0 : 1.8; };
  int step = 0;
  while (choice.current() == 2 && step < 1000) {  // up to the first probe of one thread
    choice.record(quiet(choice.current()));
    ++step;
  }
  ASSERT_EQ(choice.current(), 1) << "no probe of one thread within 1000 steps";
  choice.set_room_for_more(false);
  const auto [on_one, on_two] = run(choice, 2000, quiet);
  EXPECT_EQ(on_two, 0);
}

TEST(EngineThreadCount, OneThreadAvailableNeverProbes) {
  AdaptiveThreadCount choice(1);
  const auto [on_one, on_most] = run(choice, 1000, [](int) { return 1.0; });
  EXPECT_EQ(on_one + on_most, 1000);
  EXPECT_EQ(choice.current(), 1);
}

}  // namespace
}  // namespace ellc::engine
