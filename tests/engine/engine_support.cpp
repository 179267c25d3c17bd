#include "engine_support.hpp"

#include "ellc/scenario/packing.hpp"
#include "ellc/scenario/random.hpp"

namespace ellc::engine::testing {

using scenario::ellipsoid_overlap_test;
using scenario::generate_packing;
using scenario::PackingSpec;
using scenario::Random;

EngineSettings free_settings(NormalModel model) {
  EngineSettings settings;
  settings.contact.material = kNmc;
  settings.contact.model.normal = model;
  settings.contact.model.normal_damping = settings.contact.model.tangential_damping = 0.0;
  settings.contact.model.friction = 0.0;
  settings.contact.wall_friction = 0.0;
  settings.box = {200.0, 200.0};
  settings.max_speed = 1e6;
  settings.adaptive_threads = false;  // the tests set the thread count (omp_set_num_threads)
  return settings;
}

ParticleSet colliding_packing(std::size_t count, std::uint64_t seed, double insertion_fraction, double floor,
                              std::uint64_t velocity_seed, bool spheres) {
  PackingSpec spec;
  spec.count = count;
  spec.mean_radius = 4.0;
  spec.radius_spread = 0.1;
  spec.seed = seed;
  spec.density = kScaledDensity;
  spec.insertion_fraction = insertion_fraction;
  spec.spheres = spheres;
  ParticleSet particles = generate_packing(spec, kCollidingBox, floor, ellipsoid_overlap_test());
  Random random(velocity_seed);
  for (auto& velocity : particles.velocity)
    velocity = Eigen::Vector3d(random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1));
  return particles;
}

}  // namespace ellc::engine::testing
