// The energy balance of a pressing cycle: the work of the walls equals the change of kinetic
// energy plus what the contacts store (the law's elastic energy, the tangential springs) plus what
// they dissipate (plastic work, dashpots, sliding friction). Every term is measured on its own;
// none is defined as the remainder of the others.

#include <gtest/gtest.h>

#include <array>
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

// 60 bodies at rest between two walls; the top wall presses the bed into plastic contact, then
// lifts off. Damped and frictional, so every term is exercised. Returns the balance at the end of
// the pressing and after the release.
std::array<Balance, 2> press_and_release(bool spheres, double safety = 0.125) {
  ParticleSet particles = testing::colliding_packing(60, 7, 0.3, 0.0, 11, spheres);
  for (auto& v : particles.velocity) v.setZero();
  double top = 0.0;
  for (std::size_t k = 0; k < particles.size(); ++k)
    top = std::max(top, particles.position[k].z() + particles.bounding_radius[k]);
  EngineSettings settings = testing::free_settings(NormalModel::becker_kamlah);
  settings.box = testing::kCollidingBox;
  settings.contact.model.normal_damping = settings.contact.model.tangential_damping = 0.1;
  settings.contact.model.friction = 0.3;
  settings.contact.wall_friction = 0.3;
  settings.dt = safety * stable_time_step(particles, testing::kScaledDensity, settings.contact.material);
  Simulation sim(settings, particles, {Wall{0.0, 0.0, 1, {}}, Wall{top, 0.0, -1, {}}});
  const double initial_kinetic = sim.kinetic_energy();

  const double solid = sim.particles().total_volume() / (settings.box.lx * settings.box.ly);
  const double speed = 0.5;  // µm/µs
  sim.set_wall_velocity(kTopWall, -speed);
  while (sim.gap() > solid / 0.62) sim.step();
  const Balance loaded = balance_of(sim, initial_kinetic);
  sim.set_wall_velocity(kTopWall, speed);
  const int steps = static_cast<int>(std::lround(0.125 / safety * 2000));  // the same times at any dt
  for (int step = 0; step < 2 * steps && sim.wall_contact_count(kTopWall) > 0; ++step) sim.step();
  for (int step = 0; step < steps; ++step) sim.step();
  const Balance released = balance_of(sim, initial_kinetic);
  std::printf(
      "energy [pJ] at release: plate %.6g = kinetic %.4g + law %.4g + spring %.4g + plastic %.4g + damping "
      "%.4g + friction %.4g; residual %.3g (%.2g of the plate work)\n",
      released.plate_work, released.kinetic, released.law_elastic, released.spring, released.plastic, released.damping,
      released.friction, released.residual(), released.residual() / released.plate_work);
  return {loaded, released};
}

void expect_balance(const std::array<Balance, 2>& states, double tolerance) {
  for (const Balance& b : states) {
    EXPECT_GT(b.plate_work, 0.0);
    EXPECT_GT(b.plastic, 0.01 * b.plate_work) << "the cycle must reach plastic contacts";
    EXPECT_GT(b.damping, 0.0);
    EXPECT_GT(b.friction, 0.0);
    EXPECT_LT(std::abs(b.residual()), tolerance * b.plate_work)
        << "plate " << b.plate_work << " kinetic " << b.kinetic << " law " << b.law_elastic << " spring " << b.spring
        << " plastic " << b.plastic << " damping " << b.damping << " friction " << b.friction;
  }
}

// Spheres: the constants do not turn with the bodies, so the law's force derives from its stored
// energy, the stiffnesses are continuous (docs/contact_model.md, "The branch"), and what is left
// is the step's first-order error: released residuals −0.063, −0.029, −0.015 % at 1, ½, ¼ of the
// step. Leaving out what the spring gives up when k_t changes would make it several per cent.
TEST(EngineEnergyBalance, WallWorkEqualsStoredPlusDissipatedEnergyOnSpheresToFirstOrderInTheStep) {
  const std::array<Balance, 2> coarse = press_and_release(true);
  expect_balance(coarse, 0.001);
  const std::array<Balance, 2> fine = press_and_release(true, 0.0625);
  expect_balance(fine, 0.001);
  for (std::size_t k = 0; k < 2; ++k)
    EXPECT_LT(std::abs(fine[k].residual() / fine[k].plate_work),
              0.6 * std::abs(coarse[k].residual() / coarse[k].plate_work))
        << (k == 0 ? "loaded" : "released") << ": half the step should halve the residual";
}

// Ellipsoids: contacts whose normal and curvatures turn during a step do work that the overlap
// rate does not see, and the law's stored energy is a function of constants that change as the
// bodies rotate (docs/engine.md, "Energies"). That floor does not shrink with the step: released
// residuals of −0.75, −1.07 and −1.03 % at 1, ½ and ¼ of this step, so the 1 % asserted here holds
// at this step only, with little room.
TEST(EngineEnergyBalance, WallWorkEqualsStoredPlusDissipatedEnergyOnEllipsoidsUpToTheirRotationFloor) {
  expect_balance(press_and_release(false), 0.01);
}

}  // namespace
}  // namespace ellc::engine
