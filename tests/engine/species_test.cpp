// Several species (ContactSettings::species, ParticleSet::species): a pair of different species
// feels E_e of eq. (3) and Y = min(Y_I, Y_J) of its two materials; two species of one material are
// the one-species run bit for bit; a state written with species reads back with them.

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "engine_support.hpp"

namespace ellc::engine {
namespace {

using testing::free_settings;
using testing::kNmc;

// A softer additive: a tenth of NMC's modulus, a twentieth of its yield stress.
constexpr Material kAdditive{14200.0, 0.35, 395.0};

// Two spheres of radius R at rest, overlapping by `overlap` along x, of species 0 and 1.
Simulation two_spheres(const Material& first, const Material& second, double overlap) {
  EngineSettings settings = free_settings(NormalModel::becker_kamlah);
  settings.contact.species = {first, second};
  ParticleSet particles;
  constexpr double kRadius = 4.0;
  const Eigen::Vector3d axes = Eigen::Vector3d::Constant(kRadius);
  particles.add(0, axes, 1e-3, Eigen::Vector3d(20.0, 20.0, 50.0), Eigen::Quaterniond::Identity(), 0);
  particles.add(1, axes, 1e-3, Eigen::Vector3d(20.0 + 2.0 * kRadius - overlap, 20.0, 50.0),
                Eigen::Quaterniond::Identity(), 1);
  return Simulation(settings, std::move(particles), {Wall{0.0, 0.0, 1}, Wall{100.0, 0.0, -1}});
}

// Hertz for two spheres of radius 4: F = 4/3 E_e sqrt(R_e) δ^{3/2}, R_e = 2, with eq. (3) by hand.
double hertz_by_hand(const Material& a, const Material& b, double overlap) {
  const double effective_modulus = 1.0 / ((1.0 - a.poisson_ratio * a.poisson_ratio) / a.youngs_modulus +
                                          (1.0 - b.poisson_ratio * b.poisson_ratio) / b.youngs_modulus);
  return 4.0 / 3.0 * effective_modulus * std::sqrt(2.0) * std::pow(overlap, 1.5);
}

TEST(EngineSpecies, MixedPairFeelsEquationThreeByHand) {
  constexpr double kOverlap = 2e-3;  // µm: elastic for both materials and the mix
  const Simulation sim = two_spheres(kNmc, kAdditive, kOverlap);
  const double expected = hertz_by_hand(kNmc, kAdditive, kOverlap);
  EXPECT_NEAR(sim.particles().force[1].x(), expected, 1e-9 * expected);
  EXPECT_NEAR(sim.particles().force[0].x(), -expected, 1e-9 * expected);
  // Not the one-material values: NMC alone is far stiffer.
  EXPECT_GT(hertz_by_hand(kNmc, kNmc, kOverlap), 3.0 * expected);
  // Symmetric: the species the other way round give the same force.
  const Simulation swapped = two_spheres(kAdditive, kNmc, kOverlap);
  EXPECT_EQ(swapped.particles().force[1].x(), sim.particles().force[1].x());
}

// First yield of spheres at p0 = 1.6 Y: δ_Y = R_e (π 1.6 Y / (2 E_e))². Between the additive's
// δ_Y and NMC's the mixed pair has yielded (force below Hertz) only if Y = min(Y_I, Y_J).
TEST(EngineSpecies, MixedPairYieldsAtTheSofterYieldStress) {
  const Material additive{kAdditive.youngs_modulus, kAdditive.poisson_ratio, 100.0};
  const double effective_modulus = hertz_by_hand(kNmc, additive, 1.0) / (4.0 / 3.0 * std::sqrt(2.0));
  const auto first_yield = [&](double yield_stress) {
    const double ratio = 3.141592653589793 * 1.6 * yield_stress / (2.0 * effective_modulus);
    return 2.0 * ratio * ratio;
  };
  const double soft = first_yield(additive.yield_stress);
  const double hard = first_yield(kNmc.yield_stress);
  ASSERT_LT(10.0 * soft, hard);
  const double overlap = std::sqrt(soft * hard);
  const Simulation sim = two_spheres(kNmc, additive, overlap);
  EXPECT_LT(sim.particles().force[1].x(), 0.9 * hertz_by_hand(kNmc, additive, overlap));
  // Below the softer δ_Y it is still Hertz.
  const Simulation elastic = two_spheres(kNmc, additive, 0.5 * soft);
  const double hertz = hertz_by_hand(kNmc, additive, 0.5 * soft);
  EXPECT_NEAR(elastic.particles().force[1].x(), hertz, 1e-9 * hertz);
}

// A colliding packing split into two species of the same material is the one-species run.
TEST(EngineSpecies, TwoIdenticalSpeciesAreOneSpeciesBitwise) {
  ParticleSet particles = testing::colliding_packing(60, 11, 0.3, 0.0, 5);
  EngineSettings settings = free_settings(NormalModel::becker_kamlah);
  settings.contact.model.friction = 0.3;
  settings.contact.model.normal_damping = 0.05;
  settings.contact.model.tangential_damping = 0.05;
  settings.gravity = Eigen::Vector3d(0.0, 0.0, -0.5);
  settings.box = testing::kCollidingBox;
  const std::array<Wall, 2> walls{Wall{0.0, 0.0, 1}, Wall{200.0, -0.2, -1}};
  Simulation one(settings, particles, walls);
  EngineSettings two_settings = settings;
  two_settings.contact.species = {kNmc, kNmc};
  ParticleSet split = particles;
  for (std::size_t k = 0; k < split.size(); ++k) split.species[k] = static_cast<std::uint16_t>(k % 2);
  Simulation two(two_settings, split, walls);
  for (int step = 0; step < 400; ++step) {
    one.step();
    two.step();
  }
  ASSERT_GT(one.contact_counts().particle_contacts + one.contact_counts().wall_contacts, 0U);
  const ParticleSet& a = one.particles();
  const ParticleSet& b = two.particles();
  for (std::size_t k = 0; k < a.size(); ++k) {
    ASSERT_EQ(a.position[k], b.position[k]) << "particle " << k;
    ASSERT_EQ(a.velocity[k], b.velocity[k]) << "particle " << k;
    ASSERT_EQ(a.angular_velocity[k], b.angular_velocity[k]) << "particle " << k;
    ASSERT_EQ(a.force[k], b.force[k]) << "particle " << k;
  }
  EXPECT_EQ(one.plastic_dissipation(), two.plastic_dissipation());
  EXPECT_EQ(one.wall_work(kTopWall), two.wall_work(kTopWall));
}

TEST(EngineSpecies, StateKeepsTheSpecies) {
  const Simulation sim = two_spheres(kNmc, kAdditive, 1e-3);
  std::stringstream state;
  sim.write_state(state);
  Simulation copy = two_spheres(kAdditive, kNmc, 0.0);
  copy.read_state(state);
  EXPECT_EQ(copy.particles().species, sim.particles().species);
  EXPECT_EQ(copy.particles().species, (std::vector<std::uint16_t>{0, 1}));
}

TEST(EngineSpecies, ParticleOfAnUnknownSpeciesIsRefused) {
  EngineSettings settings = free_settings(NormalModel::becker_kamlah);
  ParticleSet particles;
  particles.add(7, Eigen::Vector3d::Constant(4.0), 1e-3, Eigen::Vector3d(20.0, 20.0, 50.0),
                Eigen::Quaterniond::Identity(), 1);
  try {
    const Simulation sim(settings, std::move(particles), {Wall{0.0, 0.0, 1}, Wall{100.0, 0.0, -1}});
    FAIL() << "a particle of species 1 with one material was accepted";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("particle 7 is of species 1"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace ellc::engine
