// particle-timesteps per second of pair_style ellipsoid/bk on a dense packing of ellipsoids, next
// to LAMMPS's own pair_style granular (hertz/material, Mindlin friction) on the same lattice as
// spheres of the same volume, in the same process. Single MPI rank.
//
//   bench_lammps [--benchmark_min_time=2] [--benchmark_format=json]
//
// Both systems: periodic simple-cubic lattice of 10 x 10 x 10 particles, spacing 9.0 um, NMC
// (E = 142000 MPa, nu = 0.25), friction 0.3, every neighbor pair starting in contact (volume
// fraction 0.6). Ellipsoids: semi-axes 6 x 5 x 4.2 um, random orientations, Becker-Kamlah normal
// law. Spheres: radius (6 * 5 * 4.2)^(1/3) = 5.01 um, Hertz. Each iteration runs 20 steps after a
// 200-step settling run; counters give particle-timesteps/s and contacts per particle.
//
// SpheresEngineVsGranular: the built-in engine (engine::Simulation, normal = hertz) against
// pair_style granular hertz/material on one sphere packing (integrations/lammps/sphere_slab.hpp:
// fcc, 13 x 13 x 13 cubic cells = 8788 spheres, periodic in x and y, free surfaces in z; undamped, frictionless Hertz;
// the same positions, radii, masses, velocities, time step and skin), one thread each (omp_set_num_threads(1)). Each
// iteration runs 20 steps of each engine, interleaved, so that the machine's load falls on both;
// the ratio engine / LAMMPS is a counter of the same run (thread CPU time, and wall time).
// ELLC_BENCH_SPHERES_CELLS overrides the 13 cells per side.

#include <benchmark/benchmark.h>
#include <mpi.h>
#include <omp.h>

#include <time.h>

#include <chrono>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "lammps_includes.hpp"
#include "lammps_session.hpp"
#include "pair_ellipsoid_bk.hpp"
#include "register_styles.hpp"
#include "sphere_slab.hpp"

#include <input.h>

namespace {

constexpr int kCells = 10;
constexpr int kStepsPerIteration = 20;
constexpr int kSettleSteps = 1500;  // SpheresEngineVsGranular: untimed, engine only (sphere_slab.hpp)

using Session = ellc_lammps::LammpsSession;

std::vector<std::string> lattice(const std::string& atom_style, const std::string& boundary = "p p p") {
  const std::string n = std::to_string(kCells);
  return {"units micro",
          "atom_style " + atom_style,
          "boundary " + boundary,
          "lattice sc 9.0",
          "region box block 0 " + n + " 0 " + n + " 0 " + n,
          "create_box 1 box",
          "create_atoms 1 box",
          "neighbor 1.0 bin",
          "neigh_modify every 1 delay 0 check yes",
          "timestep 5e-5",
          "velocity all create 5e12 8675309 dist gaussian mom yes rot no"};
}

void report(benchmark::State& state, double contacts_per_particle) {
  const double particle_steps = static_cast<double>(kCells * kCells * kCells) * kStepsPerIteration;
  state.counters["particle_timesteps_per_s"] =
      benchmark::Counter(particle_steps, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["contacts_per_particle"] = contacts_per_particle;
}

// Builds the packing with `setup`, settles it for 200 steps, then times kStepsPerIteration steps
// per benchmark iteration.
void time_steps(benchmark::State& state, const Session& session, const std::string& atom_style,
                const std::vector<std::string>& setup, const std::string& boundary = "p p p") {
  auto commands = lattice(atom_style, boundary);
  commands.insert(commands.end(), setup.begin(), setup.end());
  commands.emplace_back("run 200");
  session.run(commands);
  const std::string step = "run " + std::to_string(kStepsPerIteration) + " pre no post no";
  for (auto _ : state) session.run({step});
}

void EllipsoidBK(benchmark::State& state) {
  const Session session;
  time_steps(
      state, session, "ellipsoid",
      {"set type 1 shape 12 10 8.4", "set type 1 quat/random 4711", "set type 1 density 4.7", "pair_style ellipsoid/bk",
       "pair_coeff 1 1 1.42e8 0.25 7.9e6 friction 0.3 damping 0.1 tangential_damping 0.1",
       "fix integrate all nve/asphere"});
  const auto* pair = dynamic_cast<const ellc_lammps::PairEllipsoidBK*>(session.lmp->force->pair);
  report(state, 2.0 * static_cast<double>(pair->touching_pairs()) / (kCells * kCells * kCells));
}

// The same with the built-in engine's narrow-phase setting (one Newton step of the common normal
// per time step from the warm start, narrow_phase_final_step 1e-3, as `ellc export-lammps`
// writes it) instead of LAMMPS's default solve to rounding.
void EllipsoidBKEngineSolve(benchmark::State& state) {
  const Session session;
  time_steps(
      state, session, "ellipsoid",
      {"set type 1 shape 12 10 8.4", "set type 1 quat/random 4711", "set type 1 density 4.7", "pair_style ellipsoid/bk",
       "pair_coeff 1 1 1.42e8 0.25 7.9e6 friction 0.3 damping 0.1 tangential_damping 0.1 "
       "narrow_phase_final_step 1e-3",
       "fix integrate all nve/asphere"});
  const auto* pair = dynamic_cast<const ellc_lammps::PairEllipsoidBK*>(session.lmp->force->pair);
  report(state, 2.0 * static_cast<double>(pair->touching_pairs()) / (kCells * kCells * kCells));
}

// The same packing between the two planes of fix wall/ellipsoid/bk (z not periodic): the lattice
// spans z = 0 … 81 µm, the planes at −4.5 and 85.5 µm press the bottom and top layers (≈ 200 of
// the 1000 particles touch a plane). Against EllipsoidBK it gives the cost of the wall contacts.
void EllipsoidBKWalls(benchmark::State& state) {
  const Session session;
  time_steps(state, session, "ellipsoid",
             {"set type 1 shape 12 10 8.4", "set type 1 quat/random 4711", "set type 1 density 4.7",
              "change_box all z final -10 95 units box", "pair_style ellipsoid/bk",
              "pair_coeff 1 1 1.42e8 0.25 7.9e6 friction 0.3 damping 0.1 tangential_damping 0.1",
              "fix walls all wall/ellipsoid/bk zplane -4.5 85.5 material particle friction 0.3",
              "fix integrate all nve/asphere"},
             "p p f");
  const auto* pair = dynamic_cast<const ellc_lammps::PairEllipsoidBK*>(session.lmp->force->pair);
  report(state, 2.0 * static_cast<double>(pair->touching_pairs()) / (kCells * kCells * kCells));
}

void GranularHertzMaterial(benchmark::State& state) {
  const Session session;
  time_steps(state, session, "sphere",
             {"set type 1 diameter 10.0266", "set type 1 density 4.7", "comm_modify vel yes", "pair_style granular",
              "pair_coeff * * hertz/material 1.42e8 0.1 0.25 tangential mindlin NULL 1.0 0.3",
              "fix integrate all nve/sphere", "compute touching all contact/atom",
              "compute contacts all reduce sum c_touching", "thermo_style custom step c_contacts"});
  session.run({"run 0"});
  auto* modify = session.lmp->modify;
  const double contacts = modify->compute[modify->find_compute("contacts")]->compute_scalar();
  report(state, contacts / (kCells * kCells * kCells));
}

// CPU time of the calling thread, s (both engines run on this thread only).
double thread_cpu_seconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

void SpheresEngineVsGranular(benchmark::State& state) {
  namespace slab_ns = ellc_lammps::sphere_slab;
  const char* cells_text = std::getenv("ELLC_BENCH_SPHERES_CELLS");
  const int cells = cells_text != nullptr ? std::atoi(cells_text) : 13;
  const slab_ns::SphereSlab slab = slab_ns::make_slab(cells, cells, cells, kSettleSteps);
  const auto engine = slab_ns::engine_simulation(slab);
  state.counters["contacts_per_particle_at_start"] =
      2.0 * static_cast<double>(engine->contact_counts().particle_contacts) / static_cast<double>(slab.radius.size());
  const Session session;
  slab_ns::setup_lammps(session.lmp, slab);
  const std::string step = "run " + std::to_string(kStepsPerIteration) + " pre no post no";
  double engine_cpu = 0.0, lammps_cpu = 0.0, engine_wall = 0.0, lammps_wall = 0.0;
  using Clock = std::chrono::steady_clock;
  for (auto _ : state) {
    double cpu = thread_cpu_seconds();
    auto wall = Clock::now();
    for (int k = 0; k < kStepsPerIteration; ++k) engine->step();
    engine_cpu += thread_cpu_seconds() - cpu;
    engine_wall += std::chrono::duration<double>(Clock::now() - wall).count();
    cpu = thread_cpu_seconds();
    wall = Clock::now();
    session.run({step});
    lammps_cpu += thread_cpu_seconds() - cpu;
    lammps_wall += std::chrono::duration<double>(Clock::now() - wall).count();
  }
  const double particle_steps =
      static_cast<double>(slab.radius.size()) * kStepsPerIteration * static_cast<double>(state.iterations());
  state.counters["engine_particle_steps_per_cpu_s"] = particle_steps / engine_cpu;
  state.counters["lammps_particle_steps_per_cpu_s"] = particle_steps / lammps_cpu;
  state.counters["ratio_engine_over_lammps_cpu"] = lammps_cpu / engine_cpu;
  state.counters["ratio_engine_over_lammps_wall"] = lammps_wall / engine_wall;
  state.counters["particles"] = static_cast<double>(slab.radius.size());
  state.counters["engine_threads"] = engine->thread_count();
  state.counters["engine_rebuilds"] = static_cast<double>(engine->neighbour_rebuilds());
  state.counters["lammps_rebuilds"] = static_cast<double>(session.lmp->neighbor->ncalls);
  state.counters["engine_contacts_per_particle"] =
      2.0 * static_cast<double>(engine->contact_counts().particle_contacts) / static_cast<double>(slab.radius.size());
  session.run({"run 0"});
  state.counters["lammps_contacts_per_particle"] = slab_ns::lammps_contacts_per_particle(session.lmp);
}

BENCHMARK(EllipsoidBK)->Unit(benchmark::kMillisecond);
BENCHMARK(EllipsoidBKEngineSolve)->Unit(benchmark::kMillisecond);
BENCHMARK(EllipsoidBKWalls)->Unit(benchmark::kMillisecond);
BENCHMARK(GranularHertzMaterial)->Unit(benchmark::kMillisecond);
// 15 iterations: 300 steps of each engine, as bench_dem times.
BENCHMARK(SpheresEngineVsGranular)->Unit(benchmark::kMillisecond)->Iterations(15)->UseRealTime();

}  // namespace

int main(int argc, char** argv) {
  omp_set_num_threads(
      1);  // one thread each (omp_set_num_threads(1)). the engine's OpenMP (LAMMPS runs serial, no OMP styles)
  MPI_Init(&argc, &argv);
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  MPI_Finalize();
  return 0;
}
