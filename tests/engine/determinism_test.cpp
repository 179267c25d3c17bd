// Results independent of the thread count and of skipping the pairs proven apart, bit for bit.
// (Restart equivalence through the scenario runner: tests/scenario/restart_test.cpp.)

#include <gtest/gtest.h>
#include <omp.h>

#include "ellc/engine/time_step.hpp"
#include "engine_support.hpp"
#include "support/simulation_state.hpp"

namespace ellc::engine {
namespace {

using ellc::test::state_bytes;

// The thread test: 100 ellipsoids inserted at 40 % solid with random velocities between a fixed
// floor and a descending plate, every loop threaded (threshold 0): hundreds of collisions.
constexpr int kThreadSteps = 400;

struct CollidingRun {
  int threads = 1;
  bool skip_proven_separated = true;
  bool some_spheres = false;       // every third body a sphere inside its ellipsoid: all three pair paths
  bool alternate_threads = false;  // 1 and `threads` threads in turn, a switch before every step
  bool adaptive_threads = false;   // the engine's own choice between 1 and `threads`
  std::size_t particles = 100;
  int steps = kThreadSteps;
  std::vector<double> fixed_pair_cuts{};  // empty: the engine balances the threads' ranges
  bool nested = false;                    // step inside an outer parallel region: the engine's regions get one thread
};

struct CollidingResult {
  std::string state;
  std::size_t pairs_proven_apart = 0;  // at the end
  std::size_t pairs = 0;               // in the neighbour list at the end
  double damping_dissipation = 0.0;
  std::uint64_t pairs_taken = 0;  // by a thread from another's range
};

CollidingResult run_colliding(const CollidingRun& run) {
  const int previous = omp_get_max_threads();
  omp_set_num_threads(run.threads);
  const ParticleSet ellipsoids = testing::colliding_packing(run.particles, 3, 0.4, 0.0, 9);
  ParticleSet particles;
  for (std::size_t slot = 0; slot < ellipsoids.size(); ++slot) {
    const Eigen::Vector3d& axes = ellipsoids.semi_axes[slot];
    particles.add(ellipsoids.id[slot],
                  run.some_spheres && slot % 3 == 0 ? Eigen::Vector3d::Constant(axes.minCoeff()) : axes,
                  testing::kScaledDensity, ellipsoids.position[slot], ellipsoids.orientation[slot]);
    particles.velocity[slot] = ellipsoids.velocity[slot];
  }
  EngineSettings settings = testing::free_settings(NormalModel::becker_kamlah);
  settings.contact.model.friction = 0.3;
  settings.contact.model.normal_damping = settings.contact.model.tangential_damping = 0.05;
  settings.box = testing::kCollidingBox;
  settings.dt = stable_time_step(particles, testing::kScaledDensity, settings.contact.material);
  settings.parallel_threshold = 0;
  settings.skip_proven_separated = run.skip_proven_separated;
  settings.adaptive_threads = run.adaptive_threads;
  settings.fixed_pair_cuts = run.fixed_pair_cuts;
  double top = 0.0;
  for (std::size_t slot = 0; slot < particles.size(); ++slot)
    top = std::max(top, particles.position[slot].z() + particles.bounding_radius[slot]);
  Simulation sim(settings, particles, {Wall{0.0, 0.0, 1, {}}, Wall{top, -0.5, -1, {}}});
  std::size_t contacts = 0;
  const auto run_steps = [&] {
    for (int step = 0; step < run.steps; ++step) {
      if (run.alternate_threads) omp_set_num_threads(step % 2 == 0 ? 1 : run.threads);
      sim.step();
      contacts += sim.contact_counts().particle_contacts;
    }
  };
  if (run.nested) {
    const int levels = omp_get_max_active_levels();
    omp_set_max_active_levels(1);
    int inner_team = 0;
#pragma omp parallel num_threads(2)
    {
#pragma omp single
      {
#pragma omp parallel num_threads(run.threads)
        {
#pragma omp single
          inner_team = omp_get_num_threads();
        }
        run_steps();
      }
    }
    omp_set_max_active_levels(levels);
    EXPECT_EQ(inner_team, 1) << "a nested region should get one thread, fewer than the engine asks for";
  } else {
    run_steps();
  }
  omp_set_num_threads(previous);
  EXPECT_GT(contacts, 1000U) << "the test needs many contacts";
  return {state_bytes(sim), sim.pairs_proven_apart(), sim.pairs().size(), sim.damping_dissipation(),
          sim.pairs_taken_by_other_threads()};
}

std::string run_with_threads(int threads) { return run_colliding({threads}).state; }

// The engine may change the thread count between any two steps (settings.adaptive_threads):
// a run whose count alternates 1, 2, 1, … every step ends in the same bits as one thread.
TEST(EngineDeterminism, ThreadCountChangedEveryStepGivesTheSameState) {
  CollidingRun alternating{2};
  alternating.alternate_threads = true;
  CollidingRun adaptive{2};
  adaptive.adaptive_threads = true;
  const std::string one = run_with_threads(1);
  EXPECT_TRUE(run_colliding(alternating).state == one) << "switching the thread count changed the results";
  EXPECT_TRUE(run_colliding(adaptive).state == one) << "the adaptive thread count changed the results";
}

TEST(EngineDeterminism, OneAndTwoThreadsGiveBitwiseEqualStates) {
  const std::string one = run_with_threads(1);
  const std::string two = run_with_threads(2);
  ASSERT_EQ(one.size(), two.size());
  EXPECT_TRUE(one == two) << "the state after " << kThreadSteps << " steps depends on the thread count";
}

// The step's energy tallies are summed over fixed chunks of the pair list: on one thread as each
// pair is evaluated, with threads chunk by chunk afterwards. A list of several chunks must give
// the same bits both ways (the state holds the tallies).
TEST(EngineDeterminism, OneAndTwoThreadsAgreeOverSeveralPairChunks) {
  CollidingRun one{1};
  one.particles = 2500;
  one.steps = 60;
  CollidingRun two = one;
  two.threads = 2;
  const CollidingResult a = run_colliding(one);
  const CollidingResult b = run_colliding(two);
  EXPECT_GT(a.pairs, 2U * 4096U) << "the test needs a pair list of several chunks";
  EXPECT_GT(a.damping_dissipation, 0.0);
  EXPECT_TRUE(a.state == b.state) << "the energy tallies depend on the thread count";
}

// Threads own contiguous ranges of the pair list and take pairs from each other's ranges when they
// run out (simulation_forces.cpp, compute_forces_threaded). Where the cuts lie and who takes what must
// change nothing: lopsided fixed cuts make the thread with the short range take most of the other's
// pairs (a particle then sums some of its pairs in the loop and the rest after it), three threads
// on this machine's cores take pairs whenever one is descheduled, and the pair list spans several
// tally chunks.
TEST(EngineDeterminism, ThreadRangesAndTakenPairsGiveTheSameState) {
  CollidingRun one{1};
  one.particles = 2500;
  one.steps = 60;
  const CollidingResult reference = run_colliding(one);
  EXPECT_GT(reference.pairs, 2U * 4096U) << "the test needs a pair list of several chunks";
  CollidingRun lopsided = one;
  lopsided.threads = 2;
  lopsided.fixed_pair_cuts = {0.02};
  const CollidingResult taken = run_colliding(lopsided);
  EXPECT_GT(taken.pairs_taken, 1000U) << "the thread with the short range should take pairs from the other";
  EXPECT_TRUE(taken.state == reference.state) << "taking pairs from another thread's range changed the state";
  CollidingRun three = one;
  three.threads = 3;
  EXPECT_TRUE(run_colliding(three).state == reference.state) << "three balanced ranges changed the state";
  CollidingRun uneven = one;
  uneven.threads = 3;
  uneven.fixed_pair_cuts = {0.5, 0.51};  // one nearly empty range
  EXPECT_TRUE(run_colliding(uneven).state == reference.state) << "an almost empty range changed the state";
  CollidingRun empty = one;
  empty.threads = 4;
  empty.fixed_pair_cuts = {0.3, 0.3, 0.7};  // an empty range: its thread owns no pair and no first pair
  EXPECT_TRUE(run_colliding(empty).state == reference.state) << "an empty range changed the state";
}

// A parallel region may get fewer threads than it asks for (nested in another region, or under
// OMP_DYNAMIC): the threaded pair loop then has ranges without an owner and evaluates the pairs
// after its region, as one thread does (compute_forces_threaded). The state must be the same.
TEST(EngineDeterminism, ASmallerTeamThanAskedForGivesTheSameState) {
  CollidingRun nested{2};
  nested.nested = true;
  EXPECT_TRUE(run_colliding(nested).state == run_with_threads(1)) << "a one-thread team changed the state";
}

// Pairs proven apart are skipped (docs/engine.md): the skipped test would have found them apart,
// so skipping must change nothing at all, for ellipsoid, sphere and mixed pairs alike. (A bound
// that forgets the rotation of the bodies makes this fail.)
TEST(EngineDeterminism, SkippingPairsProvenApartChangesNothing) {
  for (const bool some_spheres : {false, true}) {
    const CollidingResult skipping = run_colliding({2, true, some_spheres});
    const CollidingResult testing_all = run_colliding({2, false, some_spheres});
    EXPECT_GT(skipping.pairs_proven_apart, 20U) << "the test needs pairs that are skipped";
    EXPECT_EQ(testing_all.pairs_proven_apart, 0U);
    ASSERT_EQ(skipping.state.size(), testing_all.state.size());
    EXPECT_TRUE(skipping.state == testing_all.state)
        << "skipping pairs proven apart changed the state (spheres mixed in: " << some_spheres << ")";
  }
}

}  // namespace
}  // namespace ellc::engine
