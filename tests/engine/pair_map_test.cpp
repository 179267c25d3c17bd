// The pair map: candidate pairs are found across the periodic boundary, keyed by ids, and
// contact histories survive a rebuild and a reordering of the particle slots.

#include <gtest/gtest.h>

#include "ellc/contact/contact_energy.hpp"
#include "ellc/engine/broad_phase.hpp"
#include "ellc/scenario/random.hpp"
#include "support/nmc.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace ellc::engine {
namespace {

using scenario::Random;

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
  before[0].history.max_overlap = 0.25;                              // active: δ_* > 0
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
  ContactCache& cache = before[0].cache;
  cache.constants =
      make_contact_constants(mix(test::kNmc, test::kNmc), {1.0, 1.0}, {1.0, 1.0}, 0.0, 2.0, HertzMode::hale);
  history.max_overlap = 10.0 * cache.constants.yield_overlap;
  const double work = plastic_work(cache.constants, history.max_overlap);
  EXPECT_GT(work, 0.0);
  std::vector<PairSlot> none;
  EXPECT_EQ(carry_over_history(before, none), work);
}

// The merge over threads (fixed chunks of the old list) moves the same histories and returns the
// same released work, bit for bit, as one merge: 10 000 old pairs, of which a fifth left the new
// list while touching (each releasing its plastic work), the new list holding pairs on both sides
// of every chunk boundary.
TEST(EnginePairMap, ThreadedHistoryMergeEqualsOneMerge) {
  Random random(5);
  const ContactConstants constants =
      make_contact_constants(mix(test::kNmc, test::kNmc), {1.0, 1.0}, {1.0, 1.0}, 0.0, 2.0, HertzMode::hale);
  std::vector<PairSlot> before, after;
  for (std::uint32_t k = 0; k < 10000; ++k) {
    PairSlot pair;
    pair.key = pair_key(k, k + 20000);
    pair.history.max_overlap = random.uniform() < 0.7 ? random.uniform(0.5, 20.0) * constants.yield_overlap : 0.0;
    pair.history.warm_valid = 1.0;
    pair.cache.constants = constants;
    pair.cache.last_overlap = random.uniform();
    before.push_back(pair);
    if (random.uniform() < 0.8) {
      PairSlot fresh;
      fresh.key = pair.key;
      after.push_back(fresh);
    }
    if (k % 3 == 0) {  // a pair the old list did not have
      PairSlot fresh;
      fresh.key = pair_key(k, k + 40000);
      after.push_back(fresh);
    }
  }
  std::sort(after.begin(), after.end(), [](const PairSlot& a, const PairSlot& b) { return a.key < b.key; });
  std::vector<PairSlot> one = after, threaded = after;
  const double serial = carry_over_history(before, one, 1);
  EXPECT_GT(serial, 0.0);
  const double parallel = carry_over_history(before, threaded, 2);
  EXPECT_EQ(parallel, serial);
  ASSERT_EQ(one.size(), threaded.size());
  for (std::size_t k = 0; k < one.size(); ++k) {
    EXPECT_EQ(one[k].history.max_overlap, threaded[k].history.max_overlap) << k;
    EXPECT_EQ(one[k].cache.last_overlap, threaded[k].cache.last_overlap) << k;
    EXPECT_EQ(one[k].history.warm_valid, threaded[k].history.warm_valid) << k;
  }
}

// Every pair whose bounding spheres come closer than their radii plus `skin` under the minimum
// image in x and y, by testing all pairs; keys sorted.
std::vector<PairKey> brute_force_keys(const ParticleSet& particles, const Box& box, double skin) {
  std::vector<PairKey> keys;
  const auto image = [](double d, double length) { return d - length * std::round(d / length); };
  for (std::size_t a = 0; a < particles.size(); ++a)
    for (std::size_t b = a + 1; b < particles.size(); ++b) {
      const Eigen::Vector3d raw = particles.position[b] - particles.position[a];
      const Eigen::Vector3d d(image(raw.x(), box.lx), image(raw.y(), box.ly), raw.z());
      const double reach = particles.bounding_radius[a] + particles.bounding_radius[b] + skin;
      if (d.squaredNorm() < reach * reach)
        keys.push_back(
            pair_key(std::min(particles.id[a], particles.id[b]), std::max(particles.id[a], particles.id[b])));
    }
  std::sort(keys.begin(), keys.end());
  return keys;
}

// The cell list finds exactly the pairs a brute-force search over all pairs (minimum image in x
// and y) finds, sorted by key as the history merge needs, and the same list for any thread count.
// Ids are shuffled against the slots so that key order and slot order differ.
TEST(EnginePairMap, CellListEqualsBruteForceSortedByKey) {
  const Box box{40.0, 30.0};
  Random random(21);
  ParticleSet particles;
  std::vector<std::uint32_t> ids(400);
  for (std::uint32_t k = 0; k < ids.size(); ++k) ids[k] = 3 * k + 7;
  for (std::size_t k = ids.size() - 1; k > 0; --k)  // Fisher–Yates
    std::swap(ids[k], ids[static_cast<std::size_t>(random.uniform() * static_cast<double>(k + 1))]);
  for (std::uint32_t id : ids) {
    const Eigen::Vector3d axes(random.uniform(0.5, 2.0), random.uniform(0.5, 2.0), random.uniform(0.5, 2.0));
    const Eigen::Vector3d centre(random.uniform(0.0, box.lx), random.uniform(0.0, box.ly), random.uniform(0.0, 25.0));
    particles.add(id, axes, 1.0, centre, random.rotation());
  }
  const double skin = 0.3;
  const std::vector<PairKey> expected = brute_force_keys(particles, box, skin);
  ASSERT_GT(expected.size(), 100U);
  const auto serial = find_candidate_pairs(particles, box, skin, 1);
  ASSERT_EQ(serial.size(), expected.size());
  for (std::size_t k = 0; k < expected.size(); ++k) {
    EXPECT_EQ(serial[k].key, expected[k]);
    EXPECT_LT(particles.id[serial[k].i], particles.id[serial[k].j]);  // i is the smaller id
    const Eigen::Vector3d seen = particles.position[serial[k].j] + serial[k].shift - particles.position[serial[k].i];
    EXPECT_LE(std::abs(seen.x()), 0.5 * box.lx);  // the shift gives the nearest image
    EXPECT_LE(std::abs(seen.y()), 0.5 * box.ly);
  }
  for (const int threads : {2, 3, 7}) {  // as many id ranges as threads, of uneven sizes for 3 and 7
    const auto threaded = find_candidate_pairs(particles, box, skin, threads);
    ASSERT_EQ(threaded.size(), serial.size()) << threads;
    for (std::size_t k = 0; k < serial.size(); ++k) {
      EXPECT_EQ(threaded[k].key, serial[k].key) << threads;
      EXPECT_EQ(threaded[k].i, serial[k].i) << threads;
      EXPECT_EQ(threaded[k].j, serial[k].j) << threads;
      EXPECT_EQ(threaded[k].shift, serial[k].shift) << threads;
    }
  }
}

// Issue 19: the cell grid is sparse and its indices 64-bit, so memory follows the particles, not
// the box. Spheres of radius 1e-4 µm in a 4·10⁵ µm box would need ~10¹⁸ dense cells (an `int`
// cell count overflowed, and a 4·10⁵ µm box of ordinary particles took 3.9 GB): clusters of
// touching tiny spheres, one across each periodic boundary, are found exactly as by brute force.
TEST(EnginePairMap, TinyParticlesInAHugeBoxNeedMemoryForTheParticlesOnly) {
  const Box box{4e5, 4e5};
  const double radius = 1e-4;
  Random random(7);
  ParticleSet particles;
  std::uint32_t id = 0;
  const auto add = [&](const Eigen::Vector3d& centre) {
    particles.add(id++, Eigen::Vector3d::Constant(radius), 1.0, centre, Eigen::Quaterniond::Identity());
  };
  for (int cluster = 0; cluster < 200; ++cluster) {  // a chain of three touching spheres each
    const Eigen::Vector3d start(random.uniform(0.0, box.lx - 1.0), random.uniform(0.0, box.ly - 1.0),
                                random.uniform(0.0, 1e5));
    for (int k = 0; k < 3; ++k) add(start + Eigen::Vector3d(1.9 * radius * k, 0.0, 0.0));
  }
  add({box.lx - 0.5 * radius, 10.0, 3.0});  // across x = 0 from the next one
  add({0.5 * radius, 10.0, 3.0});
  add({20.0, box.ly - 0.5 * radius, 3.0});  // across y = 0
  add({20.0, 0.5 * radius, 3.0});
  const double skin = 0.1 * radius;
  const auto pairs = find_candidate_pairs(particles, box, skin, 2);
  const std::vector<PairKey> expected = brute_force_keys(particles, box, skin);
  ASSERT_EQ(expected.size(), 200U * 2U + 2U);  // two pairs per chain, one per boundary
  ASSERT_EQ(pairs.size(), expected.size());
  for (std::size_t k = 0; k < expected.size(); ++k) EXPECT_EQ(pairs[k].key, expected[k]);
}

}  // namespace
}  // namespace ellc::engine
