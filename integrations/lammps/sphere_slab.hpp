#pragma once
// One sphere packing, two engines: the built-in engine (engine::Simulation, normal = hertz) and
// LAMMPS's pair_style granular hertz/material, set up on the same positions, radii, masses,
// velocities, box, time step and neighbour skin. bench_lammps times both on it
// (SpheresEngineVsGranular); tests/lammps/sphere_slab_test.cpp checks that both see the same
// contacts and forces at step 0.
//
// The packing: a face-centred cubic lattice of nx × ny × nz cubic cells (4 spheres each),
// periodic in x and y, radii 5 µm ± 0.2 %, centres jittered by ± 5 nm (seeded), nearest-neighbour
// distance 0.99 × the mean diameter: each sphere presses its 12 neighbours by about 0.1 µm
// (δ/R ≈ 2 %). Frictionless spheres need a lattice that is stable under compression: a
// simple-cubic one shears and collapses within a few hundred steps, an fcc one holds. z is
// bounded, in both engines, by planes 3 cells away from the slab that no sphere reaches during a
// run (LAMMPS: boundary p p f; the engine: its two walls). Both see free surfaces and no wall
// contacts, so the engine's box (periodic in x, y only) and LAMMPS's agree without a wall model.
// The engine first settles the lattice (global drag, make_slab). The slab then drifts along x at
// a speed that covers half the skin in 50 steps, so both engines rebuild their neighbour lists
// during a run (11–12 times in 300 steps). Along z the settled slab carries no load, so its bonds
// with a z component only just touch: the contact count drifts during a run (7.5 → 6.0 per
// sphere in bench_lammps), the same in both engines.
//
// Contact model: plain Hertz, F = (4/3) E_e sqrt(R_e) δ^{3/2}, no damping, no friction. Both
// engines mix E_e by eq. (3) of docs/model.md: E_e = [(1 − ν²)/E + (1 − ν²)/E]⁻¹ = E / (2(1 − ν²))
// for the one material (LAMMPS: hertz/material's mix_stiffnessE). Units: the engine's (µm, µs,
// ng, µN, MPa); LAMMPS runs in `units lj` with the same numbers, a consistent unit system too.

#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "ellc/engine/simulation.hpp"
#include "ellc/engine/time_step.hpp"
#include "lammps_includes.hpp"

#include <input.h>
#include <library.h>

namespace ellc_lammps::sphere_slab {

inline constexpr double kMeanRadius = 5.0;   // µm
inline constexpr double kDensity = 4.7;      // ng/µm³ (NMC with mass scaling 1000)
inline constexpr double kYoungs = 142000.0;  // MPa
inline constexpr double kPoisson = 0.25;

struct SphereSlab {
  std::vector<Eigen::Vector3d> centre;
  std::vector<double> radius;
  std::vector<Eigen::Vector3d> velocity;
  std::vector<double> mass;          // ng: the engine's (ParticleSet::add), given to LAMMPS as it is
  double lx = 0.0, ly = 0.0;         // periodic
  double z_low = 0.0, z_high = 0.0;  // the bounding planes
  double dt = 0.0;                   // µs: the engine's stable time step for these spheres
  double skin = 0.0;                 // µm: the engine's default, 0.2 of the mean radius
};

// The built-in engine on the slab: plain Hertz, undamped, frictionless, one thread (no adaptive
// thread count; the caller keeps OMP_NUM_THREADS=1). Particle ids are the slab's indices.
// drag_rate: make_slab's settling only.
inline std::unique_ptr<ellc::engine::Simulation> engine_simulation(const SphereSlab& slab, double drag_rate = 0.0) {
  using namespace ellc::engine;
  ParticleSet particles;
  for (std::size_t n = 0; n < slab.radius.size(); ++n) {
    particles.add(static_cast<std::uint32_t>(n), Eigen::Vector3d::Constant(slab.radius[n]), kDensity, slab.centre[n],
                  Eigen::Quaterniond::Identity());
    particles.velocity[n] = slab.velocity[n];
  }
  EngineSettings settings;
  settings.contact.material = {kYoungs, kPoisson, 1.0};  // Y: unused by the hertz normal model
  settings.contact.model = ellc::ContactModel{};         // no damping, no friction
  settings.contact.model.normal = ellc::NormalModel::hertz;
  settings.contact.wall_friction = 0.0;
  settings.box = {slab.lx, slab.ly};
  settings.dt = slab.dt;
  settings.skin = slab.skin;
  settings.adaptive_threads = false;
  settings.drag_rate = drag_rate;
  const std::array<Wall, 2> walls{Wall{slab.z_low, 0.0, 1, {}}, Wall{slab.z_high, 0.0, -1, {}}};
  return std::make_unique<Simulation>(settings, std::move(particles), walls);
}

// The packing described above, with its settings, after `settle_steps` steps of the engine with
// a global viscous drag from the lattice at rest (the free surfaces let the slab expand along z;
// without settling, that expansion wave opens most contacts during a timed run).
inline SphereSlab make_slab(int nx, int ny, int nz, int settle_steps, std::uint32_t seed = 2026) {
  SphereSlab slab;
  const double spacing = std::sqrt(2.0) * 0.99 * 2.0 * kMeanRadius;  // the cubic cell
  slab.lx = nx * spacing;
  slab.ly = ny * spacing;
  slab.z_low = -3.0 * spacing;
  slab.z_high = (nz + 3) * spacing;
  const std::array<Eigen::Vector3d, 4> basis{Eigen::Vector3d(0.25, 0.25, 0.25), Eigen::Vector3d(0.75, 0.75, 0.25),
                                             Eigen::Vector3d(0.75, 0.25, 0.75), Eigen::Vector3d(0.25, 0.75, 0.75)};
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        for (const Eigen::Vector3d& offset : basis) {
          const Eigen::Vector3d site = spacing * (Eigen::Vector3d(i, j, k) + offset);
          slab.centre.push_back(site + 0.005 * Eigen::Vector3d(unit(random), unit(random), unit(random)));
          slab.radius.push_back(kMeanRadius * (1.0 + 0.002 * unit(random)));
        }
  ellc::engine::ParticleSet probe;
  for (std::size_t n = 0; n < slab.radius.size(); ++n)
    probe.add(static_cast<std::uint32_t>(n), Eigen::Vector3d::Constant(slab.radius[n]), kDensity, slab.centre[n],
              Eigen::Quaterniond::Identity());
  slab.mass = probe.mass;
  slab.dt = ellc::engine::stable_time_step(probe, kDensity, {kYoungs, kPoisson, 1.0});
  slab.skin = 0.2 * kMeanRadius;
  slab.velocity.assign(slab.radius.size(), Eigen::Vector3d::Zero());
  if (settle_steps > 0) {
    const auto settling = engine_simulation(slab, 0.5);
    for (int step = 0; step < settle_steps; ++step) settling->step();
    const auto& particles = settling->particles();
    for (std::size_t slot = 0; slot < particles.size(); ++slot)
      slab.centre[particles.id[slot]] = particles.position[slot];  // wrapped into [0, lx) × [0, ly)
  }
  slab.velocity.clear();
  const double speed = 0.5 * slab.skin / (50.0 * slab.dt);
  for (std::size_t n = 0; n < slab.radius.size(); ++n) slab.velocity.push_back(speed * Eigen::Vector3d::UnitX());
  return slab;
}

// LAMMPS on the slab: atom ids are the slab's indices + 1. Ends with `run 0` (forces at step 0).
// compute "contacts" is the number of touching pairs × 2 (compute contact/atom, summed).
inline void setup_lammps(LAMMPS_NS::LAMMPS* lmp, const SphereSlab& slab) {
  auto run = [lmp](const std::string& command) { lmp->input->one(command); };
  const auto text = [](double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.17g", value);
    return std::string(buffer);
  };
  run("units lj");
  run("atom_style sphere");
  run("atom_modify map array");
  run("boundary p p f");
  run("comm_modify vel yes");
  run("region box block 0 " + text(slab.lx) + " 0 " + text(slab.ly) + " " + text(slab.z_low) + " " + text(slab.z_high) +
      " units box");
  run("create_box 1 box");
  const auto count = static_cast<int>(slab.radius.size());
  std::vector<int> ids(slab.radius.size()), types(slab.radius.size(), 1);
  std::vector<double> x, v;
  for (int n = 0; n < count; ++n) {
    ids[static_cast<std::size_t>(n)] = n + 1;
    for (int d = 0; d < 3; ++d) {
      x.push_back(slab.centre[static_cast<std::size_t>(n)][d]);
      v.push_back(slab.velocity[static_cast<std::size_t>(n)][d]);
    }
  }
  lammps_create_atoms(lmp, count, ids.data(), types.data(), x.data(), v.data(), nullptr, 0);
  // Radii and masses straight into the per-atom arrays: the engine's numbers.
  LAMMPS_NS::Atom* atom = lmp->atom;
  for (int local = 0; local < atom->nlocal; ++local) {
    const auto n = static_cast<std::size_t>(atom->tag[local] - 1);
    atom->radius[local] = slab.radius[n];
    atom->rmass[local] = slab.mass[n];
  }
  run("neighbor " + text(slab.skin) + " bin");
  run("neigh_modify every 1 delay 0 check yes");
  run("timestep " + text(slab.dt));
  run("pair_style granular");
  run("pair_coeff * * hertz/material " + text(kYoungs) + " 0.0 " + text(kPoisson) +
      " tangential linear_nohistory 0.0 0.0");
  run("fix integrate all nve/sphere");
  run("compute touching all contact/atom");
  run("compute contacts all reduce sum c_touching");
  run("thermo_style custom step c_contacts");
  run("run 0");
}

// Touching pairs × 2 / spheres, LAMMPS, at the end of the last run (call `run 0` first).
inline double lammps_contacts_per_particle(LAMMPS_NS::LAMMPS* lmp) {
  auto* modify = lmp->modify;
  auto* contacts = modify->compute[modify->find_compute("contacts")];
  return contacts->compute_scalar() / static_cast<double>(lmp->atom->natoms);
}

}  // namespace ellc_lammps::sphere_slab
