// bench_law: ns per normal-force evaluation for a batch of 10^6 contacts in mixed regimes,
// next to plain Hertz on the same contacts in the same run.
//
//  * BM_Law / BM_Hertz: force only, from prebuilt contact constants (a DEM with fixed contact
//    geometry, or LAMMPS with constants cached per pair).
//  * BM_LawOnKeptCurveVsHertz: the same with the unloading curve of δ_* kept with the contact
//    (evaluate_contact_on_curve), as a caller with fixed constants does (evaluate_along_path, a
//    pair with prebuilt constants): derived once per unloading episode, not per call. The curves
//    are prebuilt untimed, like the constants.
//  * BM_LawWithConstants / BM_HertzWithShape: the DEM path where curvatures move every step, so
//    the constants are rebuilt from (κ, α) before each force.
// The ratio counter of the Law benchmarks is against the matching Hertz baseline, measured in
// the same process first.
#include <benchmark/benchmark.h>

#include <chrono>
#include <random>
#include <vector>

#include "ellc/law/contact_law.hpp"

namespace {
using namespace ellc;

constexpr std::size_t kContacts = 1'000'000;
constexpr std::size_t kGeometries = 1024;  // distinct constant sets, cycled through the batch

struct Batch {
  std::vector<ContactConstants> constants;  // kGeometries
  std::vector<PrincipalCurvatures> curvature_i, curvature_j;
  std::vector<double> alpha;
  std::vector<std::uint32_t> geometry;  // per contact
  std::vector<double> overlap, max_overlap;
  std::vector<UnloadingCurve> unloading;  // per contact, unloading_curve(constants, max_overlap)
  std::vector<double> mean_radius_sum;
};

const Batch& batch() {
  static const Batch b = [] {
    Batch result;
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> radius(2.0, 10.0), aspect(0.5, 2.0), angle(0.0, 3.14159);
    const ContactMaterial material = mix({142000.0, 0.25, 7900.0}, {142000.0, 0.25, 7900.0});
    for (std::size_t g = 0; g < kGeometries; ++g) {
      const double ri = radius(rng), rj = radius(rng);
      const PrincipalCurvatures ki{aspect(rng) / ri, aspect(rng) / ri}, kj{aspect(rng) / rj, aspect(rng) / rj};
      result.curvature_i.push_back(ki);
      result.curvature_j.push_back(kj);
      result.alpha.push_back(angle(rng));
      result.mean_radius_sum.push_back(ri + rj);
      result.constants.push_back(
          make_contact_constants(material, ki, kj, result.alpha.back(), ri + rj, HertzMode::hale));
    }
    // Mixed regimes: a fifth each elastic, elastic–plastic, fully plastic; two fifths unloading.
    std::uniform_int_distribution<std::uint32_t> pick(0, kGeometries - 1);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (std::size_t i = 0; i < kContacts; ++i) {
      const std::uint32_t g = pick(rng);
      const ContactConstants& c = result.constants[g];
      double overlap = 0.0, max_overlap = 0.0;
      switch (i % 5) {
        case 0: overlap = unit(rng) * c.yield_overlap; break;
        case 1: overlap = c.yield_overlap + unit(rng) * (c.plastic_limit_overlap - c.yield_overlap); break;
        case 2: overlap = c.plastic_limit_overlap * (1.0 + unit(rng)); break;
        default:
          max_overlap = c.yield_overlap * (1.5 + 10.0 * unit(rng));
          overlap = max_overlap * (0.5 + 0.5 * unit(rng));
      }
      result.geometry.push_back(g);
      result.overlap.push_back(overlap);
      result.max_overlap.push_back(max_overlap);
      result.unloading.push_back(max_overlap > c.yield_overlap ? unloading_curve(c, max_overlap) : UnloadingCurve{});
    }
    return result;
  }();
  return b;
}

// Times the baseline and the law over the same batch in the same iteration, alternating, so
// that both see the same machine state; reports both and their ratio.
template <class Baseline, class Law>
void compare(benchmark::State& state, Baseline baseline, Law law) {
  const Batch& b = batch();
  double baseline_seconds = 0.0, law_seconds = 0.0;
  auto time_loop = [&b](auto per_contact) {
    const auto start = std::chrono::steady_clock::now();
    double sum = 0.0;
    for (std::size_t i = 0; i < kContacts; ++i) sum += per_contact(b, i);
    benchmark::DoNotOptimize(sum);
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  for (auto _ : state) {
    const double base = time_loop(baseline);
    const double ours = time_loop(law);
    baseline_seconds += base;
    law_seconds += ours;
    state.SetIterationTime(ours);
  }
  const double evaluations = static_cast<double>(state.iterations()) * kContacts;
  state.counters["law_ns"] = 1e9 * law_seconds / evaluations;
  state.counters["hertz_ns"] = 1e9 * baseline_seconds / evaluations;
  state.counters["ratio"] = law_seconds / baseline_seconds;
}

const ContactMaterial kMaterial = mix({142000.0, 0.25, 7900.0}, {142000.0, 0.25, 7900.0});

// The baseline of the force-only benchmarks: plain Hertz, F = C δ^{3/2}, eq. (10). A lambda, not a
// function, so that compare() inlines it as it inlines the law.
constexpr auto plain_hertz = [](const Batch& b, std::size_t i) {
  const ContactConstants& c = b.constants[b.geometry[i]];
  return c.hertz_coefficient * b.overlap[i] * std::sqrt(b.overlap[i]);
};

// Force only, constants prebuilt per contact.
void BM_LawVsHertz(benchmark::State& state) {
  compare(state, plain_hertz, [](const Batch& b, std::size_t i) {
    return evaluate_contact(b.constants[b.geometry[i]], b.overlap[i], b.max_overlap[i]).force;
  });
}

// Force only, constants and the unloading curve of each contact's δ_* prebuilt.
void BM_LawOnKeptCurveVsHertz(benchmark::State& state) {
  compare(state, plain_hertz, [](const Batch& b, std::size_t i) {
    return evaluate_contact_on_curve(b.constants[b.geometry[i]], b.overlap[i], b.max_overlap[i], b.unloading[i]).force;
  });
}

// Constants rebuilt from curvatures before every force, as in a DEM step.
void BM_LawWithConstantsVsHertzWithShape(benchmark::State& state) {
  compare(
      state,
      [](const Batch& b, std::size_t i) {
        const std::uint32_t g = b.geometry[i];
        const HertzShape shape =
            hertz_shape(relative_curvature(b.curvature_i[g], b.curvature_j[g], b.alpha[g]), HertzMode::hale);
        return hertz_contact(shape, kMaterial.effective_modulus, b.overlap[i]).force;
      },
      [](const Batch& b, std::size_t i) {
        const std::uint32_t g = b.geometry[i];
        const ContactConstants c = make_contact_constants(kMaterial, b.curvature_i[g], b.curvature_j[g], b.alpha[g],
                                                          b.mean_radius_sum[g], HertzMode::hale);
        return evaluate_contact(c, b.overlap[i], b.max_overlap[i]).force;
      });
}

BENCHMARK(BM_LawVsHertz)->UseManualTime()->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_LawOnKeptCurveVsHertz)->UseManualTime()->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_LawWithConstantsVsHertzWithShape)->UseManualTime()->Unit(benchmark::kMillisecond)->MinTime(2.0);
}  // namespace
