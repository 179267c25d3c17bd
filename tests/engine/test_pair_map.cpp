// The pair map: candidate pairs are found across the periodic boundary, keyed by ids, and
// contact histories survive a rebuild and a reordering of the particle slots.

#include <gtest/gtest.h>

#include "ellc/engine/broad_phase.hpp"
#include "ellc/engine/contact_force.hpp"

namespace ellc::engine {
namespace {

ParticleSet three_spheres(bool reversed) {
  ParticleSet particles;
  const Eigen::Vector3d a(1.0, 5.0, 5.0), b(19.5, 5.0, 5.0), c(10.0, 15.0, 5.0);  // a–b touch across x = 0
  const auto add = [&](std::uint32_t id, const Eigen::Vector3d& x) {
    particles.add(id, Eigen::Vector3d::Constant(1.0), 1.0, x, Eigen::Quaterniond::Identity());
  };
  if (reversed) {
    add(2, c), add(1, b), add(0, a);
  } else {
    add(0, a), add(1, b), add(2, c);
  }
  return particles;
}

TEST(EnginePairMap, PeriodicPairKeyedByIds) {
  const Box box{20.0, 20.0};
  const auto pairs = find_candidate_pairs(three_spheres(false), box, 0.1);
  ASSERT_EQ(pairs.size(), 1U);
  EXPECT_EQ(pairs[0].key, pair_key(0, 1));
  EXPECT_DOUBLE_EQ(pairs[0].shift.x(), -20.0);  // j = id 1 seen through the x boundary
}

TEST(EnginePairMap, HistorySurvivesRebuildAndReordering) {
  const Box box{20.0, 20.0};
  auto before = find_candidate_pairs(three_spheres(false), box, 0.1);
  before[0].history.max_overlap = 0.25;
  before[0].history.active = true;
  auto after = find_candidate_pairs(three_spheres(true), box, 0.1);  // slots reversed
  ASSERT_EQ(after.size(), 1U);
  EXPECT_EQ(after[0].key, pair_key(0, 1));
  EXPECT_EQ(carry_over_history(before, after), 0.0);
  EXPECT_EQ(after[0].history.max_overlap, 0.25);
  EXPECT_EQ(after[0].i, 2U);  // slot of id 0 in the reversed set
  EXPECT_EQ(after[0].j, 1U);
  EXPECT_DOUBLE_EQ(after[0].shift.x(), -20.0);
}

TEST(EnginePairMap, DroppedActiveContactReleasesItsWork) {
  const Box box{20.0, 20.0};
  auto before = find_candidate_pairs(three_spheres(false), box, 0.1);
  ContactHistory& history = before[0].history;
  history.active = true;
  history.constants = make_contact_constants(mix(Material{142000.0, 0.25, 7900.0}, Material{142000.0, 0.25, 7900.0}),
                                             {1.0, 1.0}, {1.0, 1.0}, 0.0, 2.0, HertzMode::hale);
  history.max_overlap = 10.0 * history.constants.yield_overlap;
  const double work = plastic_work(history.constants, history.max_overlap);
  EXPECT_GT(work, 0.0);
  std::vector<PairSlot> none;
  EXPECT_EQ(carry_over_history(before, none), work);
}

}  // namespace
}  // namespace ellc::engine
