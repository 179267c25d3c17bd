// bench_geometry: ns per ellipsoid–ellipsoid narrow-phase call, warm-started and cold, against a
// sphere–sphere check on the same centres in the same run.
//
//  * Pool of 1024 overlapping pairs: aspect 1:[0.3..3]:[0.3..3], random orientations, overlap
//    0–5 % of the smaller mean radius (DEM-typical), built around a known common normal.
//  * Warm: the warm start comes from the same pair one DEM step earlier (J moved by 1e-4 r̂ and
//    turned by 1e-4 rad), which is what an engine stores per pair. WarmLargeStep: 1e-2 r̂ and
//    1e-2 rad, a hundred such steps (a stale warm start).
//  * Cold: no warm start (Perram–Wertheim start, then Newton).
//  * Counters: median_newton_iterations over the pool, sphere_ns and ratio_to_sphere (this
//    benchmark's ns per call / the sphere check's, both timed in this process).
//  * *_WithConstruction: the Ellipsoid objects are built from the poses inside the loop too, as an
//    engine that keeps poses (not Ellipsoid objects) per particle does.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>
#include <vector>

#include "ellc/contact/normal_contact.hpp"
#include "ellc/geometry/narrow_phase.hpp"
#include "ellc/geometry/wall_contact.hpp"

namespace {
using namespace ellc;

constexpr std::size_t kPairs = 1024;

struct Pool {
  std::vector<Ellipsoid> body_i, body_j;
  std::vector<NarrowPhaseWarmStart> warm;
  std::vector<double> radius_i, radius_j;  // spheres of the bodies' mean radii on the same centres
  std::vector<int> warm_iterations, cold_iterations;
};

Eigen::Quaterniond random_orientation(std::mt19937_64& rng) {
  std::normal_distribution<double> gauss;
  return Eigen::Quaterniond(gauss(rng), gauss(rng), gauss(rng), gauss(rng)).normalized();
}

Eigen::Vector3d random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> gauss;
  return Eigen::Vector3d(gauss(rng), gauss(rng), gauss(rng)).normalized();
}

Eigen::Vector3d random_axes(std::mt19937_64& rng, double mean_radius) {
  std::uniform_real_distribution<double> log_aspect(std::log(0.3), std::log(3.0));
  const Eigen::Vector3d aspect(1.0, std::exp(log_aspect(rng)), std::exp(log_aspect(rng)));
  return aspect * (mean_radius / std::cbrt(aspect.prod()));
}

int median(std::vector<int> values) {
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2), values.end());
  return values[values.size() / 2];
}

Pool make_pool(double step) {
  Pool result;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> radius(0.5, 2.0), unit(0.0, 1.0);
  while (result.body_i.size() < kPairs) {
    const double mean_i = radius(rng), mean_j = radius(rng);
    const Ellipsoid i(random_axes(rng, mean_i), {Eigen::Vector3d::Zero(), random_orientation(rng)});
    const Eigen::Vector3d axes_j = random_axes(rng, mean_j);
    const Eigen::Quaterniond orientation_j = random_orientation(rng);
    const Eigen::Vector3d n = random_unit(rng);
    const double overlap = 0.05 * unit(rng) * std::min(mean_i, mean_j);
    // J placed so that n is a common normal with this overlap.
    const Ellipsoid j_at_origin(axes_j, {Eigen::Vector3d::Zero(), orientation_j});
    const Eigen::Vector3d centre_j = i.support_point(n) - j_at_origin.support_point(-n) - overlap * n;
    const Ellipsoid j(axes_j, {centre_j, orientation_j});
    // One step earlier: J a little elsewhere and turned.
    const Eigen::Quaterniond turn(Eigen::AngleAxisd(step, random_unit(rng)));
    const Ellipsoid j_before(axes_j, {centre_j - step * mean_j * random_unit(rng), turn.inverse() * orientation_j});
    const NarrowPhaseResult before = ellipsoid_contact(i, j_before);
    if (before.status != NarrowPhaseStatus::contact) continue;
    const NarrowPhaseResult warm = ellipsoid_contact(i, j, &before.warm_start);
    const NarrowPhaseResult cold = ellipsoid_contact(i, j);
    if (warm.status != NarrowPhaseStatus::contact || cold.status != NarrowPhaseStatus::contact) continue;
    result.body_i.push_back(i);
    result.body_j.push_back(j);
    result.warm.push_back(before.warm_start);
    result.radius_i.push_back(mean_i);
    result.radius_j.push_back(mean_j);
    result.warm_iterations.push_back(warm.iterations);
    result.cold_iterations.push_back(cold.iterations);
  }
  return result;
}

const Pool& pool() {
  static const Pool p = make_pool(1e-4);
  return p;
}

const Pool& stale_pool() {
  static const Pool p = make_pool(1e-2);
  return p;
}

struct SphereContact {
  Eigen::Vector3d normal;
  Eigen::Vector3d point;
  double overlap;
};

// The baseline: the same outputs for two spheres.
SphereContact sphere_contact(const Eigen::Vector3d& centre_i, double radius_i, const Eigen::Vector3d& centre_j,
                             double radius_j) noexcept {
  const Eigen::Vector3d offset = centre_j - centre_i;
  const double distance = offset.norm();
  const Eigen::Vector3d normal = offset / distance;
  const double overlap = radius_i + radius_j - distance;
  return {normal, centre_i + (radius_i - 0.5 * overlap) * normal, overlap};
}

double sphere_ns(const Pool& p) {
  constexpr int kRounds = 2000;
  const auto start = std::chrono::steady_clock::now();
  for (int round = 0; round < kRounds; ++round)
    for (std::size_t k = 0; k < kPairs; ++k)
      benchmark::DoNotOptimize(
          sphere_contact(p.body_i[k].center(), p.radius_i[k], p.body_j[k].center(), p.radius_j[k]));
  return std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count() /
         (static_cast<double>(kRounds) * static_cast<double>(kPairs));
}

// Runs `call(k)` over the pool, then sets the ratio counters against the sphere check.
template <typename Call>
void run_against_spheres(benchmark::State& state, const Pool& p, Call call) {
  std::size_t k = 0;
  std::size_t calls = 0;
  const auto start = std::chrono::steady_clock::now();
  for (auto _ : state) {
    benchmark::DoNotOptimize(call(k));
    k = (k + 1 == kPairs) ? 0 : k + 1;
    ++calls;
  }
  const double own_ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count() /
                        static_cast<double>(calls);
  const double baseline = sphere_ns(p);
  state.counters["sphere_ns"] = baseline;
  state.counters["ratio_to_sphere"] = own_ns / baseline;
}

void BM_SphereSphere(benchmark::State& state) {
  const Pool& p = pool();
  std::size_t k = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(sphere_contact(p.body_i[k].center(), p.radius_i[k], p.body_j[k].center(), p.radius_j[k]));
    k = (k + 1 == kPairs) ? 0 : k + 1;
  }
}
BENCHMARK(BM_SphereSphere);

void BM_NarrowPhaseWarm(benchmark::State& state) {
  const Pool& p = pool();
  run_against_spheres(state, p,
                      [&p](std::size_t k) { return ellipsoid_contact(p.body_i[k], p.body_j[k], &p.warm[k]); });
  state.counters["median_newton_iterations"] = median(p.warm_iterations);
}
BENCHMARK(BM_NarrowPhaseWarm);

// The same warm starts with the DEM engine's options: one Newton step (final_step 1e-3) and A, B
// without the per-side curvatures, directions and α (EngineSettings::narrow_phase_final_step).
constexpr NarrowPhaseOptions kEngineOptions{1e-3, false};

void BM_NarrowPhaseWarmEngineOptions(benchmark::State& state) {
  const Pool& p = pool();
  run_against_spheres(state, p, [&p](std::size_t k) {
    return ellipsoid_contact(p.body_i[k], p.body_j[k], &p.warm[k], kEngineOptions);
  });
}
BENCHMARK(BM_NarrowPhaseWarmEngineOptions);

void BM_NarrowPhaseWarmLargeStep(benchmark::State& state) {
  const Pool& p = stale_pool();
  run_against_spheres(state, p,
                      [&p](std::size_t k) { return ellipsoid_contact(p.body_i[k], p.body_j[k], &p.warm[k]); });
  state.counters["median_newton_iterations"] = median(p.warm_iterations);
}
BENCHMARK(BM_NarrowPhaseWarmLargeStep);

void BM_NarrowPhaseCold(benchmark::State& state) {
  const Pool& p = pool();
  run_against_spheres(state, p, [&p](std::size_t k) { return ellipsoid_contact(p.body_i[k], p.body_j[k]); });
  state.counters["median_newton_iterations"] = median(p.cold_iterations);
}
BENCHMARK(BM_NarrowPhaseCold);

void BM_NarrowPhaseWarmWithConstruction(benchmark::State& state) {
  const Pool& p = pool();
  run_against_spheres(state, p, [&p](std::size_t k) {
    const Ellipsoid i(p.body_i[k].semi_axes(), p.body_i[k].pose());
    const Ellipsoid j(p.body_j[k].semi_axes(), p.body_j[k].pose());
    return ellipsoid_contact(i, j, &p.warm[k]);
  });
}
BENCHMARK(BM_NarrowPhaseWarmWithConstruction);

void BM_WallContact(benchmark::State& state) {
  const Pool& p = pool();
  const Plane wall{Eigen::Vector3d(0.0, 0.0, -0.4), Eigen::Vector3d::UnitZ()};
  run_against_spheres(state, p, [&p, &wall](std::size_t k) { return wall_contact(p.body_i[k], wall); });
}
BENCHMARK(BM_WallContact);

// Geometry → force (Hale): narrow phase (warm) + make_contact_constants + the law.
void BM_WarmContactToForce(benchmark::State& state) {
  const Pool& p = pool();
  const ContactMaterial material = mix({142000.0, 0.25, 7900.0}, {142000.0, 0.25, 7900.0});
  const LawParameters law;
  run_against_spheres(state, p, [&](std::size_t k) {
    const NarrowPhaseResult found = ellipsoid_contact(p.body_i[k], p.body_j[k], &p.warm[k]);
    return normal_contact(found.geometry, material, p.radius_i[k] + p.radius_j[k], HertzMode::hale, law, 0.0).law.force;
  });
}
BENCHMARK(BM_WarmContactToForce);

}  // namespace
