// The two engines of bench_lammps's SpheresEngineVsGranular on a tiny version of its sphere slab
// (integrations/lammps/sphere_slab.hpp): at step 0 the built-in engine (normal = hertz) and LAMMPS
// (pair_style granular hertz/material) find the same touching pairs, every contact force is
// Hertz's closed form F = (4/3) E_e sqrt(R_e) δ^{3/2} with E_e = E / (2(1 − ν²)) (eq. 3 of
// docs/model.md for one material), and the net force on every sphere agrees between the engines
// to 1e-9 of the largest contact force.

#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "lammps_session.hpp"
#include "sphere_slab.hpp"

namespace {

using namespace ellc_lammps::sphere_slab;

TEST(SphereSlab, EnginesAgreeAtStepZero) {
  const SphereSlab slab = make_slab(3, 3, 2, 100);
  const auto engine = engine_simulation(slab);
  const ellc_lammps::LammpsSession lammps;
  setup_lammps(lammps.lmp, slab);

  // Every engine contact against the closed form, from the centres alone.
  const double effective_modulus = kYoungs / (2.0 * (1.0 - kPoisson * kPoisson));
  std::size_t pairs = 0;
  double largest = 0.0;
  engine->for_each_contact([&](const ellc::engine::ContactView& contact) {
    ASSERT_EQ(contact.wall, -1) << "no sphere reaches a wall";
    const double ri = slab.radius[engine->particles().id[contact.i]];
    const double rj = slab.radius[engine->particles().id[contact.j]];
    const double overlap = ri + rj - (contact.other - contact.centre_i).norm();
    ASSERT_GT(overlap, 0.0);
    const double hertz = 4.0 / 3.0 * effective_modulus * std::sqrt(ri * rj / (ri + rj)) * std::pow(overlap, 1.5);
    EXPECT_NEAR(contact.force.norm(), hertz, 1e-9 * hertz);
    largest = std::max(largest, hertz);
    ++pairs;
  });
  ASSERT_GT(pairs, slab.radius.size() * 3 / 2);  // about 4 contacts per sphere, 3 nx ny nz thin
  EXPECT_DOUBLE_EQ(lammps_contacts_per_particle(lammps.lmp),
                   2.0 * static_cast<double>(pairs) / static_cast<double>(slab.radius.size()));
  EXPECT_EQ(engine->contact_counts().particle_contacts, pairs);

  // Net force on every sphere.
  const LAMMPS_NS::Atom* atom = lammps.lmp->atom;
  ASSERT_EQ(static_cast<std::size_t>(atom->nlocal), slab.radius.size());
  const auto& particles = engine->particles();
  std::vector<std::size_t> slot_of(particles.size());
  for (std::size_t slot = 0; slot < particles.size(); ++slot) slot_of[particles.id[slot]] = slot;
  for (int local = 0; local < atom->nlocal; ++local) {
    const auto id = static_cast<std::size_t>(atom->tag[local] - 1);
    const Eigen::Vector3d lammps_force(atom->f[local][0], atom->f[local][1], atom->f[local][2]);
    EXPECT_LE((lammps_force - particles.force[slot_of[id]]).norm(), 1e-9 * largest) << "sphere " << id;
  }
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  testing::InitGoogleTest(&argc, argv);
  const int result = RUN_ALL_TESTS();
  MPI_Finalize();
  return result;
}
