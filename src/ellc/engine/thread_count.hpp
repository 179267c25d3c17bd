#pragma once
// How many threads the next step uses: an adaptive choice between one thread and all of them.
//
// Fork/join with a barrier per loop is fast on idle cores and very slow when another process
// keeps a core busy: every barrier then waits for a descheduled thread (issue 16 measured two
// threads 5× slower than one with one core busy). The step's results do not depend on the thread
// count (bit for bit, tested), so the engine may change it between any two steps. This class
// times the steps and keeps the faster count: it runs the chosen count, and now and then probes
// the other one for a few steps. A probe whose first timed step is already half again slower
// than the chosen count stops there. A probe that loses at least doubles the interval to the next
// one, and stretches it until the time the probe cost is at most kProbeBudget of the steps in
// between (up to kLongestCostlyInterval): two threads 5× slower on a busy core cost about 8 steps per
// probe, so the next probe comes 800 steps later. A probe that wins, or a chosen count that slows
// down by half, starts a new round at the short interval.
//
// The caller may also say whether other processes leave room for more than one thread
// (set_room_for_more, from engine/cpu_load.hpp: at least 1.5 cores free). Without room, all
// threads are not run: a count of all falls back to one at once, and probes of all wait; when
// room returns, one comes at once. With room, the step times decide as above.
// Timing alone finds a busy core too, but only by running slow steps on it: the first window of
// all threads and every probe (issue 16's benchmark lost 4–7 % of a 300-step run to them).
//
// Pure bookkeeping of times, no clock and no OpenMP: the caller measures and asks.

#include <algorithm>
#include <limits>

namespace ellc::engine {

class AdaptiveThreadCount {
 public:
  static constexpr int kWindow = 16;                   // steps averaged for the chosen count
  static constexpr int kProbeSteps = 4;                // steps of a probe (the first one is not counted)
  static constexpr int kShortestInterval = 64;         // steps between probes after a change
  static constexpr int kLongestInterval = 1024;        // ... after probes that kept losing
  static constexpr int kLongestCostlyInterval = 4096;  // ... after probes that lost by far
  static constexpr double kProbeBudget = 0.01;         // a losing probe's extra time / the steps to the next
  static constexpr double kClearLoss = 1.5;            // a probe step this much slower ends the probe

  explicit AdaptiveThreadCount(int most_threads = 1) noexcept { reset(most_threads); }

  void reset(int most_threads) noexcept {
    most_ = std::max(1, most_threads);
    current_ = most_;
    probing_ = false;
    sum_ = 0.0;
    steps_ = 0;
    settled_mean_ = std::numeric_limits<double>::infinity();
    interval_ = kShortestInterval;
    steps_to_probe_ = kWindow;  // the first probe right after the first full window
    room_ = true;
  }

  // Whether other processes leave room for more than one thread (true until told otherwise).
  void set_room_for_more(bool room) noexcept {
    if (most_ == 1 || room == room_) return;
    room_ = room;
    if (!room) {
      if (current_ == 1 && !probing_) return;  // on one thread already: its probes wait (record)
      // All threads are running, or one thread is being probed against them: settle on one,
      // with its time still to be measured.
      current_ = 1;
      probing_ = false;
      settled_mean_ = std::numeric_limits<double>::infinity();
      start_window(interval_);
      return;
    }
    if (current_ == 1 && !probing_) {  // look again as soon as one thread's window is measured
      interval_ = kShortestInterval;
      steps_to_probe_ = 0;
    }
  }

  [[nodiscard]] int most() const noexcept { return most_; }
  // The thread count for the next step.
  [[nodiscard]] int current() const noexcept { return current_; }

  // The wall time of one step run with current() threads (steps that rebuilt the neighbour list
  // are better left out: they cost several ordinary steps).
  void record(double seconds) noexcept {
    if (most_ == 1) return;
    if (probing_) {
      if (++steps_ > 1) sum_ += seconds;  // the first step wakes the pool or lets it fall asleep
      const int timed = steps_ - 1;
      const bool clearly_losing = timed > 0 && sum_ > kClearLoss * settled_mean_ * timed;
      if (steps_ < kProbeSteps && !clearly_losing) return;
      const double probe_mean = sum_ / timed;
      probing_ = false;
      if (probe_mean < 0.97 * settled_mean_) {  // the other count is faster: keep it
        settled_mean_ = probe_mean;
        interval_ = kShortestInterval;
      } else {
        current_ = other();
        // The probe's steps (the untimed first one counted at the probe's mean) cost this many
        // steps of the chosen count beyond what the chosen count would have taken.
        // (A zero settled time, from a clock too coarse to see a step, gives no stretch.)
        const double extra_steps = settled_mean_ > 0.0 ? steps_ * (probe_mean / settled_mean_ - 1.0) : 0.0;
        const double affordable = std::min(extra_steps / kProbeBudget, static_cast<double>(kLongestCostlyInterval));
        interval_ = std::max(std::min(2 * interval_, kLongestInterval), static_cast<int>(affordable));
      }
      start_window(interval_);
      return;
    }
    sum_ += seconds;
    if (++steps_ == kWindow) {
      const double mean = sum_ / kWindow;
      if (mean > 1.5 * settled_mean_) {  // the load changed: look again now
        steps_to_probe_ = 0;
        interval_ = kShortestInterval;
      }
      settled_mean_ = mean;
      sum_ = 0.0;
      steps_ = 0;
    }
    if (--steps_to_probe_ <= 0 && settled_mean_ < std::numeric_limits<double>::infinity()) {
      if (current_ == 1 && !room_) {  // all threads would share a core: not now
        steps_to_probe_ = interval_;
        return;
      }
      probing_ = true;
      current_ = other();
      sum_ = 0.0;
      steps_ = 0;
    }
  }

 private:
  [[nodiscard]] int other() const noexcept { return current_ == 1 ? most_ : 1; }
  void start_window(int steps_to_probe) noexcept {
    sum_ = 0.0;
    steps_ = 0;
    steps_to_probe_ = steps_to_probe;
  }

  int most_ = 1;
  int current_ = 1;
  bool probing_ = false;
  double sum_ = 0.0;  // over the current window or probe
  int steps_ = 0;
  double settled_mean_ = 0.0;  // mean step time of current() over its last full window
  int interval_ = kShortestInterval;
  int steps_to_probe_ = kWindow;
  bool room_ = true;  // other processes leave room for more than one thread (set_room_for_more)
};

}  // namespace ellc::engine
