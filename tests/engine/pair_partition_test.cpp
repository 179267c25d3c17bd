// The threaded pair loop's cuts (pair_partition.hpp): pure bookkeeping of measured times.

#include "ellc/engine/pair_partition.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <vector>

namespace ellc::engine {
namespace {

TEST(PairPartition, StartsWithEqualRangesThatCoverTheList) {
  PairPartition partition;
  partition.reset(3);
  ASSERT_EQ(partition.ranges(), 3);
  EXPECT_EQ(partition.first_pair(0, 900), 0U);
  EXPECT_EQ(partition.first_pair(1, 900), 300U);
  EXPECT_EQ(partition.first_pair(2, 900), 600U);
  EXPECT_EQ(partition.first_pair(3, 900), 900U);
  EXPECT_EQ(partition.first_pair(3, 0), 0U);
}

// Pairs three times as costly in the first third of the list (cost 1 there, 2/3 in the rest): the
// balanced cut splits the cost 5/6 : 5/6, at 5/18 of the list. The cuts assume an even cost within
// each range, so each step's target is off while a range holds both kinds, but the error shrinks
// as the cut nears the balance, and each step goes half way: it converges.
TEST(PairPartition, MovesTheCutsToEqualTimes) {
  PairPartition partition;
  partition.reset(2);
  const auto time_of = [](double from, double to) {  // cost density 3 below 1/3, 1 above
    const auto cost = [](double x) { return x < 1.0 / 3.0 ? 3.0 * x : 1.0 + (x - 1.0 / 3.0); };
    return cost(to) - cost(from);
  };
  for (int step = 0; step < 60; ++step) {
    const double cut = partition.cuts()[1];
    const std::vector<double> seconds{time_of(0.0, cut), time_of(cut, 1.0)};
    partition.record(seconds);
    ASSERT_GE(partition.cuts()[1], 0.0);
    ASSERT_LE(partition.cuts()[1], 1.0);
  }
  EXPECT_NEAR(partition.cuts()[1], 5.0 / 18.0, 1e-9);
}

TEST(PairPartition, KeepsTheCutsOrderedForAnyTimes) {
  PairPartition partition;
  partition.reset(4);
  const std::vector<std::vector<double>> rounds{{1.0, 1e-9, 5.0, 1.0}, {1e-6, 1e-6, 1e-6, 10.0}, {7.0, 0.1, 0.1, 0.1}};
  for (int repeat = 0; repeat < 20; ++repeat) {
    for (const auto& seconds : rounds) {
      partition.record(seconds);
      const auto& cuts = partition.cuts();
      ASSERT_EQ(cuts.front(), 0.0);
      ASSERT_EQ(cuts.back(), 1.0);
      for (std::size_t k = 1; k < cuts.size(); ++k) ASSERT_LE(cuts[k - 1], cuts[k]);
    }
  }
}

// A clock too coarse to see a range (a zero time), or times that do not fit, change nothing.
TEST(PairPartition, IgnoresTimesItCannotUse) {
  PairPartition partition;
  partition.reset(2);
  partition.record(std::vector<double>{0.0, 1.0});
  partition.record(std::vector<double>{1.0, 2.0, 3.0});
  partition.record(std::vector<double>{1.0, std::numeric_limits<double>::infinity()});
  EXPECT_EQ(partition.cuts()[1], 0.5);
}

TEST(PairPartition, FixedCutsStay) {
  PairPartition partition;
  partition.fix(std::vector<double>{0.1, 0.7});
  EXPECT_EQ(partition.ranges(), 3);
  partition.record(std::vector<double>{1.0, 5.0, 1.0});
  EXPECT_EQ(partition.cuts()[1], 0.1);
  EXPECT_EQ(partition.cuts()[2], 0.7);
  EXPECT_EQ(partition.first_pair(1, 1000), 100U);
}

}  // namespace
}  // namespace ellc::engine
