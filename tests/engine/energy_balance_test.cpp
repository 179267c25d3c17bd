// The energy balance of a pressing cycle: the work of the walls equals the change of kinetic
// energy plus what the contacts store (the law's elastic energy, the tangential springs) plus what
// they dissipate (plastic work, dashpots, sliding friction). Every term is measured on its own;
// none is defined as the remainder of the others.

#include <gtest/gtest.h>

#include <cmath>

#include "ellc/engine/time_step.hpp"
#include "engine_support.hpp"

namespace ellc::engine {
namespace {

struct Balance {
  double plate_work = 0.0;
  double kinetic = 0.0;
  double law_elastic = 0.0;
  double spring = 0.0;
  double plastic = 0.0;
  double damping = 0.0;
  double friction = 0.0;
  [[nodiscard]] double residual() const {
    return plate_work - (kinetic + law_elastic + spring + plastic + damping + friction);
  }
};

Balance balance_of(const Simulation& sim, double initial_kinetic) {
  return {sim.wall_work(kBottomWall) + sim.wall_work(kTopWall),
          sim.kinetic_energy() - initial_kinetic,
          sim.contact_elastic_energy(),
          sim.spring_energy(),
          sim.plastic_dissipation(),
          sim.damping_dissipation(),
          sim.friction_dissipation()};
}

// 60 ellipsoids at rest between two walls; the top wall presses the bed into plastic contact,
// then lifts off. Damped and frictional, so every term is exercised.
TEST(EngineEnergyBalance, WallWorkEqualsStoredPlusDissipatedEnergy) {
  ParticleSet particles = testing::colliding_packing(60, 7, 0.3, 0.0, 11);
  for (auto& v : particles.velocity) v.setZero();
  double top = 0.0;
  for (std::size_t k = 0; k < particles.size(); ++k)
    top = std::max(top, particles.position[k].z() + particles.bounding_radius[k]);
  EngineSettings settings = testing::free_settings(NormalModel::becker_kamlah);
  settings.box = testing::kCollidingBox;
  settings.contact.model.normal_damping = settings.contact.model.tangential_damping = 0.1;
  settings.contact.model.friction = 0.3;
  settings.contact.wall_friction = 0.3;
  settings.dt = 0.125 * stable_time_step(particles, testing::kScaledDensity, settings.contact.material);
  Simulation sim(settings, particles, {Wall{0.0, 0.0, 1, {}}, Wall{top, 0.0, -1, {}}});
  const double initial_kinetic = sim.kinetic_energy();

  const double solid = sim.particles().total_volume() / (settings.box.lx * settings.box.ly);
  const double speed = 0.5;  // µm/µs
  sim.set_wall_velocity(kTopWall, -speed);
  while (sim.gap() > solid / 0.62) sim.step();
  Balance loaded = balance_of(sim, initial_kinetic);
  sim.set_wall_velocity(kTopWall, speed);
  for (int step = 0; step < 4000 && sim.wall_contact_count(kTopWall) > 0; ++step) sim.step();
  for (int step = 0; step < 2000; ++step) sim.step();
  const Balance released = balance_of(sim, initial_kinetic);

  for (const Balance& b : {loaded, released}) {
    EXPECT_GT(b.plate_work, 0.0);
    EXPECT_GT(b.plastic, 0.01 * b.plate_work) << "the cycle must reach plastic contacts";
    EXPECT_GT(b.damping, 0.0);
    EXPECT_GT(b.friction, 0.0);
    EXPECT_LT(std::abs(b.residual()), 0.01 * b.plate_work)
        << "plate " << b.plate_work << " kinetic " << b.kinetic << " law " << b.law_elastic << " spring " << b.spring
        << " plastic " << b.plastic << " damping " << b.damping << " friction " << b.friction;
  }
  std::printf(
      "energy [pJ] at release: plate %.6g = kinetic %.4g + law %.4g + spring %.4g + plastic %.4g + damping "
      "%.4g + friction %.4g; residual %.3g (%.2g of the plate work)\n",
      released.plate_work, released.kinetic, released.law_elastic, released.spring, released.plastic, released.damping,
      released.friction, released.residual(), released.residual() / released.plate_work);
}

}  // namespace
}  // namespace ellc::engine
