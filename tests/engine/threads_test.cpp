// The pair loop shared by two threads: what the TSan run of scripts/sanitizers.sh relies on.
//
// The threaded pair loop (simulation_forces.cpp) gives each thread a range of the pair list, and a
// thread that has finished takes 64-pair blocks from the back of the others. The 100-body runs of
// determinism_test.cpp have about 380 pairs, and under TSan the first thread can be through its
// range and the other's before the second has joined the parallel region (it starts 0.1-0.3 ms
// later there): the second thread then evaluates no pair, and a race in evaluate_pair() would go
// unseen. A dense packing of 1000 bodies has thousands of pairs every step, so both threads
// evaluate pairs in the same step; the states after one and after two threads must be the same
// bits.

#include <gtest/gtest.h>
#include <omp.h>

#include "ellc/engine/time_step.hpp"
#include "engine_support.hpp"
#include "support/simulation_state.hpp"

namespace ellc::engine {
namespace {

constexpr int kSteps = 100;
constexpr std::size_t kChunk = 256;  // pairs: four of the threaded loop's blocks (simulation_forces.cpp)

struct DenseRun {
  std::string state;
  std::size_t fewest_pairs = 0;  // over the steps
  std::size_t contacts = 0;      // summed over the steps
};

DenseRun run_dense(const ParticleSet& particles, int threads) {
  const int previous = omp_get_max_threads();
  omp_set_num_threads(threads);
  EngineSettings settings = testing::free_settings(NormalModel::becker_kamlah);
  settings.contact.model.friction = 0.3;
  settings.contact.model.normal_damping = settings.contact.model.tangential_damping = 0.05;
  settings.box = testing::kCollidingBox;
  settings.dt = stable_time_step(particles, testing::kScaledDensity, settings.contact.material);
  settings.parallel_threshold = 0;
  double top = 0.0;
  for (std::size_t slot = 0; slot < particles.size(); ++slot)
    top = std::max(top, particles.position[slot].z() + particles.bounding_radius[slot]);
  Simulation sim(settings, particles, {Wall{0.0, 0.0, 1, {}}, Wall{top, -0.5, -1, {}}});
  DenseRun run;
  run.fewest_pairs = sim.pairs().size();
  for (int step = 0; step < kSteps; ++step) {
    sim.step();
    run.fewest_pairs = std::min(run.fewest_pairs, sim.pairs().size());
    run.contacts += sim.contact_counts().particle_contacts;
  }
  omp_set_num_threads(previous);
  run.state = ellc::test::state_bytes(sim);
  return run;
}

TEST(EngineDeterminism, DensePackingPairLoopSharedByTwoThreads) {
  const ParticleSet particles = testing::colliding_packing(1000, 5, 0.45, 0.0, 11);
  const DenseRun one = run_dense(particles, 1);
  const DenseRun two = run_dense(particles, 2);
  EXPECT_GE(one.fewest_pairs, 8 * kChunk) << "too few pairs for both threads to share the pair loop";
  EXPECT_GT(one.contacts, 1000U) << "the test needs contacts";
  ASSERT_EQ(one.state.size(), two.state.size());
  EXPECT_TRUE(one.state == two.state) << "the dense packing's state after " << kSteps
                                      << " steps depends on the thread count";
}

}  // namespace
}  // namespace ellc::engine
