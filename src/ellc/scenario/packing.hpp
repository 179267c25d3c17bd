#pragma once
// Packing generation: N ellipsoids with a size distribution and aspect ratios 1:[lo..hi]:[lo..hi]
// in random orientations, placed without overlap by random sequential insertion into the
// periodic box above the bottom wall. The loose packing is then settled by the scenario
// (gravity + drag), see protocol_stages.hpp.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "ellc/engine/particles.hpp"
#include "ellc/engine/settings.hpp"

namespace ellc::scenario {

// One species of a packing ([[species]], docs/engine.md "Several species"): its size and shape
// distribution, density and number fraction. Its material is engine::ContactSettings::species[k].
struct SpeciesSpec {
  std::string name;
  double fraction = 1.0;       // of the particle count
  double mean_radius = 4.0;    // µm
  double radius_spread = 0.0;  // as PackingSpec's
  double aspect_min = 0.5;
  double aspect_max = 2.0;
  bool spheres = false;
  double density = 4.7e-3;  // ng/µm³, after mass scaling
};

struct PackingSpec {
  std::size_t count = 0;
  double mean_radius = 4.0;    // mean r̂ = (abc)^{1/3}, µm
  double radius_spread = 0.0;  // standard deviation of r̂ relative to the mean (normal, cut at ±2σ)
  double aspect_min = 0.5;     // b/a and c/a drawn log-uniformly in [aspect_min, aspect_max]
  double aspect_max = 2.0;
  bool spheres = false;  // a = b = c = r̂
  std::uint64_t seed = 1;
  double density = 4.7e-3;           // ng/µm³, after mass scaling
  double insertion_fraction = 0.25;  // solid fraction the insertion region is first sized for
  // `[packing] file`: the particles come from this file instead (packing_import.hpp); the fields
  // above then describe it (count, mean r̂, spheres) and this is its largest semi-axis.
  std::string file;
  double imported_bounding_radius = 0.0;
  // [[species]]: several species; the fields above then describe the blend (count, seed,
  // insertion_fraction as given; mean_radius the radius of the mean particle volume, spheres if all
  // are). Empty: one species, described by the fields above.
  std::vector<SpeciesSpec> species;
};

// The species of a packing: `species`, or the one the fields of `spec` describe.
[[nodiscard]] std::vector<SpeciesSpec> species_of(const PackingSpec& spec);

// How many particles of each species: the fractions × count, rounded by largest remainder (ties to
// the earlier species), so that the counts add up to `count`.
[[nodiscard]] std::vector<std::size_t> species_counts(const std::vector<SpeciesSpec>& species, std::size_t count);

// Overlap test for insertion; the default compares bounding spheres.
using OverlapTest = std::function<bool(const Eigen::Vector3d& axes_a, const Eigen::Vector3d& centre_a,
                                       const Eigen::Quaterniond& rotation_a, const Eigen::Vector3d& axes_b,
                                       const Eigen::Vector3d& centre_b, const Eigen::Quaterniond& rotation_b)>;

// Particles with ids 0..N−1, all above z = floor (clear of it by their bounding radius); or, when
// spec.file is set, the particles of that file (import_packing). With several species, each
// particle's species is drawn as a seeded shuffle of species_counts(), then its size and shape from
// that species' distribution; one species draws exactly what it always did.
[[nodiscard]] engine::ParticleSet generate_packing(const PackingSpec& spec, const engine::Box& box, double floor,
                                                   const OverlapTest& overlap = {});

// Exact ellipsoid overlap through the narrow phase, with the bodies inflated by `margin` (relative).
[[nodiscard]] OverlapTest ellipsoid_overlap_test(double margin = 0.02);

}  // namespace ellc::scenario
