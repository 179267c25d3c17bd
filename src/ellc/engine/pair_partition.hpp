#pragma once
// How the pair list is cut among the threads of a step: one contiguous range per thread, its
// ends chosen so that the ranges took equal time on the last step.
//
// With contiguous ranges, a particle whose pairs all lie in one thread's range takes its pair
// forces from that thread, in list order, as the one-thread loop adds them; only the particles
// whose pairs straddle a cut are summed after the loop. So the cuts change who adds, never what
// or in which order: results are the same bits wherever the cuts lie (docs/engine.md, "Threads").
// That frees the cuts to follow the measured cost: a pair proven apart costs a few ns, a touching
// ellipsoid pair about 0.7 µs, and a core shared with another process runs slower.
//
// Balance: each range's time is spread evenly over its pairs; the cuts that split that cost into
// equal parts are the target, and the cuts move half way to it per step (a noisy step moves them
// by half its error). Pure bookkeeping, no clock and no OpenMP: the caller measures.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

namespace ellc::engine {

class PairPartition {
 public:
  // Equal shares for `threads` ranges (also after a change of the thread count).
  void reset(int threads) {
    const auto count = static_cast<std::size_t>(std::max(threads, 1));
    cuts_.resize(count + 1);
    fixed_ = false;
    for (std::size_t k = 0; k <= count; ++k) cuts_[k] = static_cast<double>(k) / static_cast<double>(count);
  }

  // Fixed cuts (fractions, increasing, in (0, 1)), one fewer than the ranges; record() then
  // leaves them.
  void fix(std::span<const double> cuts) {
    reset(static_cast<int>(cuts.size()) + 1);
    for (std::size_t k = 0; k < cuts.size(); ++k) cuts_[k + 1] = std::clamp(cuts[k], cuts_[k], 1.0);
    fixed_ = true;
  }

  [[nodiscard]] int ranges() const noexcept { return static_cast<int>(cuts_.size()) - 1; }

  // The first pair of range k (k = 0 … ranges(); the last is `pairs`) for a list of `pairs`.
  [[nodiscard]] std::size_t first_pair(int k, std::size_t pairs) const noexcept {
    if (k >= ranges()) return pairs;
    const auto cut =
        static_cast<std::size_t>(std::floor(cuts_[static_cast<std::size_t>(k)] * static_cast<double>(pairs)));
    return std::min(cut, pairs);
  }

  // The wall times the ranges took this step, one per range. Times that are not all finite and
  // positive (a clock too coarse to see a range) leave the cuts where they are.
  void record(std::span<const double> seconds) {
    const std::size_t count = cuts_.size() - 1;
    if (fixed_ || seconds.size() != count || count < 2) return;
    double total = 0.0;
    for (const double s : seconds) {
      if (!(s > 0.0) || !std::isfinite(s)) return;
      total += s;
    }
    // The cost so far at each old cut is the sum of the times before it; the new cut k sits where
    // that piecewise linear cost reaches k/count of the total.
    std::size_t range = 0;
    double cost_before = 0.0;  // cost up to cuts_[range]
    target_ = cuts_;
    for (std::size_t k = 1; k < count; ++k) {
      const double wanted = total * static_cast<double>(k) / static_cast<double>(count);
      while (range + 1 < count && cost_before + seconds[range] < wanted) cost_before += seconds[range++];
      const double share = std::clamp((wanted - cost_before) / seconds[range], 0.0, 1.0);
      target_[k] = cuts_[range] + share * (cuts_[range + 1] - cuts_[range]);
    }
    for (std::size_t k = 1; k < count; ++k) cuts_[k] += 0.5 * (target_[k] - cuts_[k]);
    // Monotone by construction; kept so against rounding.
    for (std::size_t k = 1; k < count; ++k) cuts_[k] = std::clamp(cuts_[k], cuts_[k - 1], 1.0);
  }

  [[nodiscard]] const std::vector<double>& cuts() const noexcept { return cuts_; }

 private:
  std::vector<double> cuts_{0.0, 1.0};  // fractions of the pair list: 0 = c_0 ≤ c_1 ≤ … ≤ c_T = 1
  std::vector<double> target_;          // record()'s scratch (no allocation per step)
  bool fixed_ = false;
};

}  // namespace ellc::engine
