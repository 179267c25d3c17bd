// Physics of the integrator and the contact response: energy, restitution, momentum.

#include <gtest/gtest.h>

#include <cmath>

#include "ellc/engine/rigid_body.hpp"
#include "ellc/engine/time_step.hpp"
#include "ellc/geometry/narrow_phase.hpp"
#include "ellc/law/contact_constants.hpp"
#include "ellc/scenario/random.hpp"
#include "engine_support.hpp"

namespace ellc::engine {
namespace {

using scenario::Random;
using testing::free_settings;
using testing::kNmc;
using testing::kScaledDensity;

// The quaternion step is the rotation by |ω| dt about ω, to rounding, on both sides of the switch
// from the Taylor series (every DEM step) to std::sin and std::cos (turns above 0.02 rad).
TEST(RigidBody, OrientationStepIsTheExactRotation) {
  Random random(5);
  for (int sample = 0; sample < 2000; ++sample) {
    const Eigen::Vector3d axis =
        Eigen::Vector3d(random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1)).normalized();
    const double angle = std::pow(10.0, random.uniform(-9.0, -0.5));  // 10⁻⁹ … 0.3 rad in one step
    const double dt = random.uniform(0.01, 1.0);
    const Eigen::Quaterniond start(Eigen::AngleAxisd(random.uniform(0, 6.3), Eigen::Vector3d::UnitZ()) *
                                   Eigen::AngleAxisd(random.uniform(0, 6.3), Eigen::Vector3d::UnitX()));
    const Eigen::Quaterniond stepped = advance_orientation(start, axis * (angle / dt), dt);
    const Eigen::Quaterniond exact = start * Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis));
    EXPECT_LT((stepped.coeffs() - exact.coeffs()).norm(), 4e-16) << "angle " << angle;
  }
}

// A purely elastic sphere dropped on the bottom wall under gravity: kinetic + potential + the
// Hertz energy stored in the contact stays constant through the bounce (velocity Verlet,
// no damping), and the sphere comes back to its drop height.
TEST(EngineDynamics, ElasticSphereFallingOnWallConservesEnergy) {
  EngineSettings settings = free_settings(NormalModel::hertz);
  const double gravity = 0.5;
  settings.gravity = Eigen::Vector3d(0.0, 0.0, -gravity);
  const double radius = 5.0;
  const double drop = 1.0;  // µm of free fall before contact: impact at 1 µm/µs
  ParticleSet particles;
  particles.add(0, Eigen::Vector3d::Constant(radius), kScaledDensity, Eigen::Vector3d(100.0, 100.0, radius + drop),
                Eigen::Quaterniond::Identity());
  settings.dt = stable_time_step(particles, kScaledDensity, kNmc);
  Simulation sim(settings, particles, {Wall{0.0, 0.0, 1, {}}, Wall{1000.0, 0.0, -1, {}}});
  const double mass = sim.particles().mass[0];
  const auto energy = [&] {
    return sim.kinetic_energy() + mass * gravity * sim.particles().position[0].z() + sim.contact_elastic_energy();
  };
  const double initial = energy();
  double worst = 0.0;
  bool touched = false;
  double apex = 0.0;
  // Fall (2 µs), contact (~0.5 µs), rise back: 5 µs in all.
  const auto steps = static_cast<int>(5.0 / settings.dt);
  for (int step = 0; step < steps; ++step) {
    sim.step();
    worst = std::max(worst, std::abs(energy() - initial) / initial);
    touched = touched || sim.contact_counts().wall_contacts > 0;
    if (touched) apex = std::max(apex, sim.particles().position[0].z());
  }
  EXPECT_TRUE(touched);
  RecordProperty("max_relative_energy_error", std::to_string(worst));
  EXPECT_LT(worst, 2e-3) << "energy drift over the bounce";
  EXPECT_NEAR(apex, radius + drop, 2e-3 * drop) << "rebound height";
  EXPECT_EQ(sim.plastic_dissipation(), 0.0);
}

// Thornton (1997), J. Appl. Mech. 64, 383: restitution of elastic–perfectly plastic spheres,
// e = (6√3/5)^{1/2} [1 − (v_y/v)²/6]^{1/2} [ (v_y/v) / (v_y/v + 2 sqrt(6/5 − (v_y/v)²/5)) ]^{1/4}.
double thornton_restitution(double ratio) {  // ratio = v_y / v_impact ≤ 1
  return std::sqrt(6.0 * std::sqrt(3.0) / 5.0) * std::sqrt(1.0 - ratio * ratio / 6.0) *
         std::pow(ratio / (ratio + 2.0 * std::sqrt(6.0 / 5.0 - ratio * ratio / 5.0)), 0.25);
}

// Head-on collision of two equal spheres with the law in its Thornton limit (λ ≡ 1.6, docs/model.md
// §4). v_y is the impact speed whose kinetic energy m* v_y²/2 equals the Hertz work up to δ_Y.
// Tolerance 1.5 %: the time discretisation (about 30 steps per contact at dt = 0.05 estimate).
TEST(EngineDynamics, RestitutionMatchesThornton1997) {
  const double radius = 5.0;
  EngineSettings base = free_settings(NormalModel::becker_kamlah);
  base.contact.model.law = LawParameters{}.elastic_fully_plastic();
  const ContactConstants constants =
      make_contact_constants(mix(kNmc, kNmc), {1 / radius, 1 / radius}, {1 / radius, 1 / radius}, 0.0, 2 * radius,
                             HertzMode::hale, base.contact.model.law);
  ParticleSet probe;
  probe.add(0, Eigen::Vector3d::Constant(radius), kScaledDensity, Eigen::Vector3d::Zero(),
            Eigen::Quaterniond::Identity());
  const double reduced_mass = 0.5 * probe.mass[0];
  const double yield_speed =
      std::sqrt(2.0 * 0.4 * constants.hertz_coefficient * std::pow(constants.yield_overlap, 2.5) / reduced_mass);
  for (const double multiple : {3.0, 10.0, 30.0}) {
    const double speed = multiple * yield_speed;
    ParticleSet particles;
    particles.add(0, Eigen::Vector3d::Constant(radius), kScaledDensity, Eigen::Vector3d(100, 100, 100),
                  Eigen::Quaterniond::Identity());
    particles.add(1, Eigen::Vector3d::Constant(radius), kScaledDensity,
                  Eigen::Vector3d(100, 100, 100 + 2 * radius + 1e-3), Eigen::Quaterniond::Identity());
    particles.velocity[0] = Eigen::Vector3d(0, 0, 0.5 * speed);
    particles.velocity[1] = Eigen::Vector3d(0, 0, -0.5 * speed);
    EngineSettings settings = base;
    settings.dt = 0.05 * stable_time_step(particles, kScaledDensity, kNmc);
    Simulation sim(settings, particles, {Wall{-1000.0, 0.0, 1, {}}, Wall{1000.0, 0.0, -1, {}}});
    bool touched = false;
    for (int step = 0; step < 2'000'000; ++step) {
      sim.step();
      const bool contact = sim.contact_counts().particle_contacts > 0;
      touched = touched || contact;
      if (touched && !contact) break;
    }
    ASSERT_TRUE(touched);
    const double separation_speed = sim.particles().velocity[1].z() - sim.particles().velocity[0].z();
    const double restitution = separation_speed / speed;
    const double expected = thornton_restitution(1.0 / multiple);
    RecordProperty("restitution_at_" + std::to_string(static_cast<int>(multiple)) + "_vy", std::to_string(restitution));
    EXPECT_NEAR(restitution, expected, 0.015 * expected) << "v/v_y = " << multiple;
  }
}

// A sphere and an ellipsoid approaching head-on: the pair is tested while apart (so it holds a
// separating axis) and must register the contact in the step the bodies first overlap. Guards the
// separating-axis shortcut against using anything but the true shapes of both bodies.
TEST(EngineDynamics, SphereMeetsEllipsoidWhenTheyFirstOverlap) {
  EngineSettings settings = free_settings(NormalModel::hertz);
  const double speed = 0.5;  // µm/µs
  ParticleSet particles;
  particles.add(0, Eigen::Vector3d::Constant(3.0), kScaledDensity, Eigen::Vector3d(50.0, 50.0, 50.0),
                Eigen::Quaterniond::Identity());
  const Eigen::Quaterniond tilt(Eigen::AngleAxisd(0.3, Eigen::Vector3d(0.0, 1.0, 1.0).normalized()));
  particles.add(1, Eigen::Vector3d(4.0, 2.0, 2.5), kScaledDensity, Eigen::Vector3d(58.0, 50.5, 50.0), tilt);
  particles.velocity[1] = Eigen::Vector3d(-speed, 0.0, 0.0);
  settings.dt = stable_time_step(particles, kScaledDensity, kNmc);
  settings.box = {100.0, 100.0};
  Simulation sim(settings, particles, {Wall{0.0, 0.0, 1, {}}, Wall{100.0, 0.0, -1, {}}});
  const auto true_overlap = [&] {
    const ParticleSet& p = sim.particles();
    const Ellipsoid a(p.semi_axes[0], Pose{p.position[0], p.orientation[0]});
    const Ellipsoid b(p.semi_axes[1], Pose{p.position[1], p.orientation[1]});
    const NarrowPhaseResult found = ellipsoid_contact(a, b);
    return found.status == NarrowPhaseStatus::contact ? found.geometry.overlap : 0.0;
  };
  int apart_steps = 0;
  for (int step = 0; step < static_cast<int>(4.0 / speed / settings.dt); ++step) {
    sim.step();
    if (sim.contact_counts().particle_contacts > 0) break;
    ++apart_steps;
    ASSERT_EQ(true_overlap(), 0.0) << "overlapping bodies reported apart at step " << step;
  }
  EXPECT_GT(apart_steps, 10);  // the pair was evaluated (and held a separating axis) while apart
  EXPECT_EQ(sim.contact_counts().particle_contacts, 1U);
  EXPECT_GT(true_overlap(), 0.0);
  EXPECT_LT(true_overlap(), 2.0 * speed * settings.dt);  // caught in its first step of overlap
}

// The state gives a sphere's angular velocity in its body frame. The engine drops a sphere's
// orientation (align_sphere_frames), turning that into the same spin in the world frame; a free
// sphere then keeps it exactly, with no gyroscopic term and no drift of its frame.
TEST(EngineDynamics, FreeSphereKeepsItsWorldSpin) {
  EngineSettings settings = free_settings(NormalModel::hertz);
  ParticleSet particles;
  const Eigen::Quaterniond tilted(Eigen::AngleAxisd(2.1, Eigen::Vector3d(-3.0, 1.0, 2.0).normalized()));
  particles.add(0, Eigen::Vector3d::Constant(4.0), kScaledDensity, Eigen::Vector3d(100.0, 100.0, 50.0), tilted);
  const Eigen::Vector3d spin_body(0.3, -0.2, 0.5);
  particles.angular_velocity[0] = spin_body;
  settings.dt = stable_time_step(particles, kScaledDensity, kNmc);
  Simulation sim(settings, particles, {Wall{0.0, 0.0, 1, {}}, Wall{1000.0, 0.0, -1, {}}});
  const Eigen::Vector3d spin_world = sim.particles().angular_velocity[0];
  EXPECT_LT((spin_world - tilted * spin_body).norm(), 1e-15 * spin_body.norm());
  for (int step = 0; step < 1000; ++step) sim.step();
  EXPECT_EQ(sim.particles().angular_velocity[0], spin_world);
  EXPECT_EQ(sim.particles().orientation[0].coeffs(), Eigen::Quaterniond::Identity().coeffs());
}

// A sphere sliding without spin on a frictional floor under gravity ends rolling at 5/7 of its
// initial speed: friction, gravity and the normal force exert no torque about the contact point,
// so m v r + I ω is conserved there, with I = 2/5 m r². It starts with a tilted orientation, which
// the engine drops (a sphere's frame is the world frame, align_sphere_frames): its angular velocity
// is then the world one, ω = (0, v/z, 0) when rolling along x at height z, and its orientation
// stays the identity. Fails if the rotational kick or its frame is wrong.
TEST(EngineDynamics, SlidingSphereRollsAtFiveSeventhsOfItsSpeed) {
  EngineSettings settings = free_settings(NormalModel::hertz);
  const double gravity = 0.5;
  settings.gravity = Eigen::Vector3d(0.0, 0.0, -gravity);
  settings.contact.wall_friction = 0.3;
  settings.contact.model.normal_damping = settings.contact.model.tangential_damping = 0.3;
  const double radius = 5.0;
  const double speed = 0.05;  // µm/µs along x
  ParticleSet particles;
  const Eigen::Quaterniond tilted(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1.0, 2.0, 3.0).normalized()));
  particles.add(0, Eigen::Vector3d::Constant(radius), kScaledDensity, Eigen::Vector3d(100.0, 100.0, radius), tilted);
  particles.velocity[0] = Eigen::Vector3d(speed, 0.0, 0.0);
  settings.dt = stable_time_step(particles, kScaledDensity, kNmc);
  Simulation sim(settings, particles, {Wall{0.0, 0.0, 1, {}}, Wall{1000.0, 0.0, -1, {}}});
  const auto& p = sim.particles();
  EXPECT_EQ(p.orientation[0].coeffs(), Eigen::Quaterniond::Identity().coeffs());
  // Rolling: the contact point, on the floor at depth z below the centre, is at rest.
  const auto slip = [&] { return p.velocity[0].x() - p.angular_velocity[0].y() * p.position[0].z(); };
  int steps = 0;
  while (std::abs(slip()) > 1e-9 * speed && steps < 200000) {
    sim.step();
    ++steps;
  }
  ASSERT_LT(steps, 200000) << "never rolled: slip " << slip();
  // 5/7 for a rigid sphere; the lever arm is shorter by the overlap, δ/r = 0.6 % here.
  EXPECT_NEAR(p.velocity[0].x(), 5.0 / 7.0 * speed, 0.01 * speed) << steps << " steps to roll";
  EXPECT_NEAR(p.angular_velocity[0].y() * radius, 5.0 / 7.0 * speed, 0.01 * speed);
  EXPECT_LT(std::abs(p.angular_velocity[0].x()) + std::abs(p.angular_velocity[0].z()), 1e-9 * speed / radius);
  EXPECT_EQ(p.orientation[0].coeffs(), Eigen::Quaterniond::Identity().coeffs());
}

// Ellipsoids with friction and damping in a periodic box, no walls reached, no gravity: the total
// linear momentum is conserved to rounding (every contact force acts on both bodies).
TEST(EngineDynamics, MomentumIsConserved) {
  ParticleSet particles = testing::colliding_packing(60, 11, 0.3, 500.0, 5);
  Random spin(6);
  for (auto& omega : particles.angular_velocity)
    omega = Eigen::Vector3d(spin.uniform(-0.1, 0.1), spin.uniform(-0.1, 0.1), spin.uniform(-0.1, 0.1));
  EngineSettings settings = testing::free_settings(NormalModel::becker_kamlah);
  settings.contact.model.friction = 0.5;
  settings.contact.model.normal_damping = settings.contact.model.tangential_damping = 0.1;
  settings.box = testing::kCollidingBox;
  settings.dt = stable_time_step(particles, kScaledDensity, kNmc);
  const auto momentum = [](const ParticleSet& p) {
    Eigen::Vector3d total = Eigen::Vector3d::Zero();
    for (std::size_t slot = 0; slot < p.size(); ++slot) total += p.mass[slot] * p.velocity[slot];
    return total;
  };
  double scale = 0.0;
  for (std::size_t slot = 0; slot < particles.size(); ++slot)
    scale += particles.mass[slot] * particles.velocity[slot].norm();
  const Eigen::Vector3d initial = momentum(particles);
  Simulation sim(settings, particles, {Wall{-1e4, 0.0, 1, {}}, Wall{1e4, 0.0, -1, {}}});
  std::size_t contacts_seen = 0;
  for (int step = 0; step < 1500; ++step) {
    sim.step();
    contacts_seen += sim.contact_counts().particle_contacts;
  }
  EXPECT_GT(contacts_seen, 0U) << "the test needs collisions";
  EXPECT_LT((momentum(sim.particles()) - initial).norm(), 1e-12 * scale);
}

}  // namespace
}  // namespace ellc::engine
