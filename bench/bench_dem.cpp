// bench_dem: particle-timesteps per second of the DEM engine on a dense packing of 10^4
// ellipsoids (Becker–Kamlah law, Hale), and in the same run the same packing as spheres of the
// same volume with plain Hertz. The ratio ellipsoid / sphere is reported as a counter.
//
// Packing (untimed): random sequential insertion (exact ellipsoid overlap test) at 30 % solid in a
// layer of fixed height (the base grows with N), pressed by the top wall to 60 % solid in about
// 1500 steps and held for 300: a confined packing
// with several contacts per particle. The sphere run starts from the same positions (spheres of
// the same volume) after 100 untimed steps. ELLC_BENCH_DEM_PARTICLES overrides N = 10^4,
// ELLC_BENCH_DEM_STEPS the 300 timed steps (with fewer, the figure depends more on how many
// neighbour-list rebuilds, about one per 20 steps, fall into the window),
// ELLC_BENCH_DEM_FIXED_THREADS=1 switches the adaptive thread count off, ELLC_BENCH_DEM_STATE=FILE
// keeps the pressed packing in FILE for the next run (read_pressed). Counters: particle-steps/s,
// the threads the engine ran on at the end, and memory per particle (the simulation's resident
// growth, and the process's peak). bench/compare_dem.py runs it against a baseline build with a
// busy companion process; bench/scaling.py over N.

#include <benchmark/benchmark.h>

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>

#include "ellc/engine/broad_phase.hpp"
#include "ellc/engine/simulation.hpp"
#include "ellc/engine/time_step.hpp"
#include "ellc/scenario/packing.hpp"

namespace {

using namespace ellc;
using namespace ellc::engine;
using namespace ellc::scenario;

std::size_t particle_count() {
  if (const char* text = std::getenv("ELLC_BENCH_DEM_PARTICLES")) return std::strtoul(text, nullptr, 10);
  return 10000;
}

struct Packing {
  ParticleSet particles;
  Box box;
  double top = 0.0;
};

constexpr double kDensity = 4.7e-3 * 1000.0;  // ng/µm³, NMC with mass scaling 1000

const Packing& loose_packing() {
  static const Packing packing = [] {
    PackingSpec spec;
    spec.count = particle_count();
    spec.mean_radius = 4.0;
    spec.radius_spread = 0.1;
    spec.seed = 2024;
    spec.density = kDensity;
    spec.insertion_fraction = 0.3;
    Packing result;
    // The loose layer of 10^4 is about twice as tall as wide. Other N keep its height and scale
    // the base, so every N is pressed at the same wall speed to statistically the same packing
    // (a cubic scaling pressed 10^5 particles 2.2 times faster, to 1.4 times the contacts per
    // particle, which then dominated the cost per particle-step).
    constexpr double kReferenceCount = 10000.0;
    const double reference_side = std::cbrt(kReferenceCount * 4.0 / 3.0 * 3.14159 * 64.0 / 0.3 / 2.0);
    const double side = reference_side * std::sqrt(static_cast<double>(spec.count) / kReferenceCount);
    result.box = {side, side};
    const ParticleSet loose = generate_packing(spec, result.box, 0.0, ellipsoid_overlap_test());
    for (std::size_t slot = 0; slot < loose.size(); ++slot) {
      result.particles.add(loose.id[slot], loose.semi_axes[slot], spec.density, loose.position[slot],
                           loose.orientation[slot]);
      result.top = std::max(result.top, loose.position[slot].z() + loose.bounding_radius[slot]);
    }
    return result;
  }();
  return packing;
}

ParticleSet as_spheres(const ParticleSet& source, double density) {
  ParticleSet spheres;
  for (std::size_t slot = 0; slot < source.size(); ++slot)
    spheres.add(source.id[slot], Eigen::Vector3d::Constant(source.mean_radius[slot]), density, source.position[slot],
                source.orientation[slot]);
  return spheres;
}

EngineSettings bench_settings(bool spheres, const ParticleSet& particles, const Box& box) {
  EngineSettings settings;
  settings.contact.material = {142000.0, 0.25, 7900.0};
  settings.contact.model.normal = spheres ? NormalModel::hertz : NormalModel::becker_kamlah;
  settings.contact.model.normal_damping = settings.contact.model.tangential_damping = 0.3;
  settings.box = box;
  settings.dt = stable_time_step(particles, kDensity, settings.contact.material);
  settings.drag_rate = 0.5;
  settings.max_speed = 1e6;
  // ELLC_BENCH_DEM_FIXED_THREADS=1: always OMP_NUM_THREADS threads (the engine's adaptive choice
  // between one thread and all of them is on otherwise).
  settings.adaptive_threads = std::getenv("ELLC_BENCH_DEM_FIXED_THREADS") == nullptr;
  return settings;
}

// ELLC_BENCH_DEM_STATE=FILE: the pressed packing is read from FILE when FILE exists, and written
// there after pressing when it does not. Repeated runs, and the two builds bench/compare_dem.py
// interleaves, then skip the pressing (most of a run's time) and time the same packing, bit for
// bit, which tightens a comparison on a noisy machine: more rounds in the same time.
std::unique_ptr<Simulation> read_pressed(const char* path, const EngineSettings& settings, const ParticleSet& particles,
                                         const std::array<Wall, 2>& walls) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return nullptr;  // not written yet: this run presses and writes it
  auto sim = std::make_unique<Simulation>(settings, particles, walls);
  sim->read_state(in);  // throws, naming the reason, on a damaged file
  if (sim->particles().size() != particles.size())
    throw std::runtime_error(std::string("ELLC_BENCH_DEM_STATE = ") + path + " holds " +
                             std::to_string(sim->particles().size()) + " particles, expected " +
                             std::to_string(particles.size()) + " (ELLC_BENCH_DEM_PARTICLES): use one file per N");
  return sim;
}

// The loose packing pressed by the top wall to 60 % solid, then held: a dense, confined packing.
const Simulation& dense_ellipsoids() {
  static const std::unique_ptr<Simulation> simulation = [] {
    const Packing& packing = loose_packing();
    const EngineSettings settings = bench_settings(false, packing.particles, packing.box);
    std::array<Wall, 2> walls{Wall{0.0, 0.0, 1, {}}, Wall{packing.top, 0.0, -1, {}}};
    const char* state_file = std::getenv("ELLC_BENCH_DEM_STATE");
    if (state_file != nullptr)
      if (auto pressed = read_pressed(state_file, settings, packing.particles, walls)) return pressed;
    auto sim = std::make_unique<Simulation>(settings, packing.particles, walls);
    const double solid = sim->particles().total_volume() / (packing.box.lx * packing.box.ly);
    const double target_gap = solid / 0.6;
    const double speed = (packing.top - target_gap) / (1500.0 * settings.dt);  // about 1500 steps of travel
    sim->set_wall_velocity(kTopWall, -speed);
    while (sim->gap() > target_gap) sim->step();
    sim->set_wall_velocity(kTopWall, 0.0);
    for (int step = 0; step < 300; ++step) sim->step();
    if (state_file != nullptr) {
      std::ofstream out(state_file, std::ios::binary);
      sim->write_state(out);
      if (!out) throw std::runtime_error(std::string("ELLC_BENCH_DEM_STATE = ") + state_file + ": cannot write");
    }
    return sim;
  }();
  return *simulation;
}

// The slots of `from` along a Z-order (Morton) curve through the box: neighbours in space become
// neighbours in memory. The packing's ids are in insertion order, i.e. random in space.
std::vector<std::size_t> z_order(const ParticleSet& from, const Box& box, double top) {
  const auto spread = [](std::uint64_t v) {  // 21 bits → every third bit
    v &= 0x1fffff;
    v = (v | v << 32) & 0x1f00000000ffffULL;
    v = (v | v << 16) & 0x1f0000ff0000ffULL;
    v = (v | v << 8) & 0x100f00f00f00f00fULL;
    v = (v | v << 4) & 0x10c30c30c30c30c3ULL;
    v = (v | v << 2) & 0x1249249249249249ULL;
    return v;
  };
  const auto cell = [](double x, double length) {
    return static_cast<std::uint64_t>(std::clamp(x / length, 0.0, 1.0) * 2097151.0);
  };
  std::vector<std::pair<std::uint64_t, std::size_t>> keyed(from.size());
  for (std::size_t slot = 0; slot < from.size(); ++slot) {
    const Eigen::Vector3d& p = from.position[slot];
    keyed[slot] = {spread(cell(p.x(), box.lx)) | spread(cell(p.y(), box.ly)) << 1 | spread(cell(p.z(), top)) << 2,
                   slot};
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<std::size_t> order(from.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = keyed[k].second;
  return order;
}

// Copy of the dense state with fresh contact histories: ellipsoids, or spheres of the same volume.
// `spatial_order`: slots and ids renumbered along a Z-order curve (the same packing, in another
// memory order: an experiment on cache misses at large N).
std::unique_ptr<Simulation> dense(bool spheres, bool spatial_order = false) {
  const Simulation& source = dense_ellipsoids();
  const Packing& packing = loose_packing();
  ParticleSet particles;
  const ParticleSet& from = source.particles();
  std::vector<std::size_t> order(from.size());
  for (std::size_t slot = 0; slot < from.size(); ++slot) order[slot] = slot;
  if (spatial_order) order = z_order(from, packing.box, packing.top);
  for (std::size_t k = 0; k < order.size(); ++k) {
    const std::size_t slot = order[k];
    particles.add(spatial_order ? static_cast<std::uint32_t>(k) : from.id[slot],
                  spheres ? Eigen::Vector3d::Constant(from.mean_radius[slot]) : from.semi_axes[slot], kDensity,
                  from.position[slot], from.orientation[slot]);
  }
  const EngineSettings settings = bench_settings(spheres, particles, packing.box);
  auto sim = std::make_unique<Simulation>(settings, std::move(particles), source.walls());
  for (int step = 0; step < 100; ++step) sim->step();  // spheres: let the changed overlaps settle
  return sim;
}

// Resident memory of the process now, bytes (Linux /proc/self/statm; 0 elsewhere).
double resident_bytes() {
  std::ifstream statm("/proc/self/statm");
  double pages = 0.0, resident = 0.0;
  statm >> pages >> resident;
  return resident * static_cast<double>(sysconf(_SC_PAGESIZE));
}

// CPU time of the whole process (all threads), seconds.
double process_cpu_seconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const auto seconds = [](const timeval& t) {
    return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec);
  };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

double ellipsoid_rate = 0.0;
double sphere_rate = 0.0;

void run(benchmark::State& state, bool spheres, double& rate, bool spatial_order = false) {
  dense_ellipsoids();  // the shared setup, not counted in the memory of this run
  const double resident_before = resident_bytes();
  auto simulation = dense(spheres, spatial_order);
  const auto count = static_cast<double>(simulation->particles().size());
  std::int64_t steps = 0;
  const std::uint64_t taken_before = simulation->pairs_taken_by_other_threads();
  const double cpu_start = process_cpu_seconds();
  const auto start = std::chrono::steady_clock::now();
  for (auto _ : state) {
    simulation->step();
    ++steps;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double cpu_seconds = process_cpu_seconds() - cpu_start;
  rate = count * static_cast<double>(steps) / seconds;
  // CPU time per particle-step, all threads: on a loaded machine a steadier measure of the work
  // than wall time (it does not count the time the process waited for a core).
  state.counters["cpu_ns_per_particle_step"] = 1e9 * cpu_seconds / (count * static_cast<double>(steps));
  const ContactCounts counts = simulation->contact_counts();
  state.counters["particle_steps_per_s"] = rate;
  state.counters["particles"] = count;
  state.counters["contacts_per_particle"] = 2.0 * static_cast<double>(counts.particle_contacts) / count;
  state.counters["candidate_pairs_per_particle"] = static_cast<double>(simulation->pairs().size()) / count;
  state.counters["narrow_phase_failures"] = static_cast<double>(counts.narrow_phase_failures);
  state.counters["threads_at_end"] = simulation->thread_count();  // the engine's adaptive choice
  // Share of the pair evaluations a thread took from another's range (the threaded loop's balancing).
  state.counters["pairs_taken_fraction"] =
      static_cast<double>(simulation->pairs_taken_by_other_threads() - taken_before) /
      std::max(1.0, static_cast<double>(simulation->pairs().size()) * static_cast<double>(steps));
  // What this run's simulation holds (resident growth since before it was made), and the peak
  // resident memory of the whole process (the packing's setup included), bytes per particle.
  state.counters["simulation_bytes_per_particle"] = (resident_bytes() - resident_before) / count;
  // Peak resident memory of the whole process (packing setup included) per particle, bytes.
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  state.counters["peak_rss_bytes_per_particle"] = 1024.0 * static_cast<double>(usage.ru_maxrss) / count;
}

void BM_dem_ellipsoids_becker_kamlah(benchmark::State& state) { run(state, false, ellipsoid_rate); }
void BM_dem_spheres_hertz(benchmark::State& state) { run(state, true, sphere_rate); }
// The same two runs with the particles renumbered along a Z-order curve (not in bench/scaling.py's
// filter; `--benchmark_filter=dem_` runs both orders in one process, on one packing).
double ellipsoid_rate_z = 0.0, sphere_rate_z = 0.0;
void BM_z_order_dem_ellipsoids_becker_kamlah(benchmark::State& state) { run(state, false, ellipsoid_rate_z, true); }
void BM_z_order_dem_spheres_hertz(benchmark::State& state) { run(state, true, sphere_rate_z, true); }
void BM_dem_ratio_ellipsoid_over_sphere(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(ellipsoid_rate);
  state.counters["ellipsoid_particle_steps_per_s"] = ellipsoid_rate;
  state.counters["sphere_particle_steps_per_s"] = sphere_rate;
  state.counters["ratio"] = sphere_rate > 0.0 ? ellipsoid_rate / sphere_rate : 0.0;
}

// The broad phase alone: one neighbour-list build (find_candidate_pairs, one thread) of the dense
// packing, as ellipsoids and as spheres of the same volume, with the engine's skin.
void broad_phase(benchmark::State& state, bool spheres) {
  const auto simulation = dense(spheres);
  const ParticleSet& particles = simulation->particles();
  std::vector<PairSlot> pairs;
  for (auto _ : state) {
    find_candidate_pairs(particles, loose_packing().box, simulation->skin(), 1, pairs);
    benchmark::DoNotOptimize(pairs.data());
  }
  // Seconds per particle and build (printed with an SI prefix, e.g. 3.0us).
  state.counters["time_per_particle"] =
      benchmark::Counter(static_cast<double>(particles.size()),
                         benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["candidate_pairs_per_particle"] =
      static_cast<double>(pairs.size()) / static_cast<double>(particles.size());
}
void BM_broad_phase_ellipsoids(benchmark::State& state) { broad_phase(state, false); }
void BM_broad_phase_spheres(benchmark::State& state) { broad_phase(state, true); }

std::int64_t timed_steps() {
  if (const char* text = std::getenv("ELLC_BENCH_DEM_STEPS")) return std::strtol(text, nullptr, 10);
  return 300;
}

BENCHMARK(BM_dem_ellipsoids_becker_kamlah)->Unit(benchmark::kMillisecond)->Iterations(timed_steps())->UseRealTime();
BENCHMARK(BM_dem_spheres_hertz)->Unit(benchmark::kMillisecond)->Iterations(timed_steps())->UseRealTime();
BENCHMARK(BM_dem_ratio_ellipsoid_over_sphere)->Iterations(1);
BENCHMARK(BM_broad_phase_ellipsoids)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_broad_phase_spheres)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_z_order_dem_ellipsoids_becker_kamlah)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(timed_steps())
    ->UseRealTime();
BENCHMARK(BM_z_order_dem_spheres_hertz)->Unit(benchmark::kMillisecond)->Iterations(timed_steps())->UseRealTime();

}  // namespace
