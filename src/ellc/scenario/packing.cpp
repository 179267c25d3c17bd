#include "ellc/scenario/packing.hpp"
#include "ellc/scenario/packing_import.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <unordered_map>
#include <vector>

#include "ellc/geometry/narrow_phase.hpp"
#include "ellc/scenario/random.hpp"

namespace ellc::scenario {

using engine::Box;
using engine::ellipsoid_volume;
using engine::ParticleSet;

namespace {

struct Candidate {
  std::uint16_t species = 0;
  Eigen::Vector3d axes;
  Eigen::Quaterniond rotation;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double bounding = 0.0;
};

// Species 0, 1, … in the counts of species_counts(), shuffled (Fisher–Yates) with their own
// stream of the seed; all 0 without drawing for one species.
std::vector<std::uint16_t> draw_species(const std::vector<SpeciesSpec>& species, std::size_t count,
                                        std::uint64_t seed) {
  std::vector<std::uint16_t> drawn;
  drawn.reserve(count);
  const std::vector<std::size_t> counts = species_counts(species, count);
  for (std::size_t k = 0; k < counts.size(); ++k) drawn.insert(drawn.end(), counts[k], static_cast<std::uint16_t>(k));
  if (species.size() < 2) return drawn;
  Random random(seed ^ 0x5bec1e55'5bec1e55ULL);
  for (std::size_t k = drawn.size(); k > 1; --k) {
    const auto pick = std::min(k - 1, static_cast<std::size_t>(random.uniform() * static_cast<double>(k)));
    std::swap(drawn[k - 1], drawn[pick]);
  }
  return drawn;
}

std::vector<Candidate> draw_particles(const PackingSpec& spec) {
  const std::vector<SpeciesSpec> species = species_of(spec);
  const std::vector<std::uint16_t> species_index = draw_species(species, spec.count, spec.seed);
  Random random(spec.seed);
  std::vector<Candidate> drawn(spec.count);
  for (std::size_t index = 0; index < drawn.size(); ++index) {
    Candidate& particle = drawn[index];
    particle.species = species_index[index];
    const SpeciesSpec& kind = species[particle.species];
    double deviation = random.normal();
    deviation = std::clamp(deviation, -2.0, 2.0);
    const double radius = kind.mean_radius * std::max(0.05, 1.0 + kind.radius_spread * deviation);
    if (kind.spheres) {
      particle.axes.setConstant(radius);
    } else {
      const double log_low = std::log(kind.aspect_min);
      const double log_high = std::log(kind.aspect_max);
      const Eigen::Vector3d ratios(1.0, std::exp(random.uniform(log_low, log_high)),
                                   std::exp(random.uniform(log_low, log_high)));
      particle.axes = ratios * (radius / std::cbrt(ratios.prod()));  // (abc)^{1/3} = r̂
    }
    particle.rotation = random.rotation();
    particle.bounding = particle.axes.maxCoeff();
  }
  return drawn;
}

// Uniform cells with periodic x, y; z unbounded (hashed).
class InsertionGrid {
 public:
  InsertionGrid(const Box& box, double cell) : box_(box) {
    nx_ = std::max(1, static_cast<int>(box.lx / cell));
    ny_ = std::max(1, static_cast<int>(box.ly / cell));
    cell_x_ = box.lx / nx_;
    cell_y_ = box.ly / ny_;
    cell_z_ = cell;
  }
  void insert(std::size_t index, const Eigen::Vector3d& centre) { cells_[key_of(cell_of(centre))].push_back(index); }

  template <typename Visit>
  bool any_neighbour(const Eigen::Vector3d& centre, Visit&& visit) const {
    const auto [ix, iy, iz] = cell_of(centre);
    std::vector<std::int64_t> seen;
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const std::int64_t key = key_of({wrap(ix + dx, nx_), wrap(iy + dy, ny_), iz + dz});
          if (std::find(seen.begin(), seen.end(), key) != seen.end()) continue;
          seen.push_back(key);
          const auto found = cells_.find(key);
          if (found == cells_.end()) continue;
          for (std::size_t other : found->second)
            if (visit(other)) return true;
        }
    return false;
  }

 private:
  struct Cell {
    int x, y, z;
  };
  static int wrap(int value, int n) { return (value % n + n) % n; }
  [[nodiscard]] Cell cell_of(const Eigen::Vector3d& centre) const {
    return {std::clamp(static_cast<int>(std::floor(centre.x() / cell_x_)), 0, nx_ - 1),
            std::clamp(static_cast<int>(std::floor(centre.y() / cell_y_)), 0, ny_ - 1),
            static_cast<int>(std::floor(centre.z() / cell_z_))};
  }
  [[nodiscard]] std::int64_t key_of(Cell cell) const {
    return (static_cast<std::int64_t>(cell.z) * ny_ + cell.y) * nx_ + cell.x;
  }
  Box box_;
  int nx_ = 1, ny_ = 1;
  double cell_x_ = 1.0, cell_y_ = 1.0, cell_z_ = 1.0;
  std::unordered_map<std::int64_t, std::vector<std::size_t>> cells_;
};

}  // namespace

std::vector<SpeciesSpec> species_of(const PackingSpec& spec) {
  if (!spec.species.empty()) return spec.species;
  SpeciesSpec one;
  one.mean_radius = spec.mean_radius;
  one.radius_spread = spec.radius_spread;
  one.aspect_min = spec.aspect_min;
  one.aspect_max = spec.aspect_max;
  one.spheres = spec.spheres;
  one.density = spec.density;
  return {one};
}

std::vector<std::size_t> species_counts(const std::vector<SpeciesSpec>& species, std::size_t count) {
  std::vector<std::size_t> counts(species.size(), 0);
  if (species.empty()) return counts;
  std::vector<double> remainder(species.size(), 0.0);
  std::size_t given = 0;
  for (std::size_t k = 0; k < species.size(); ++k) {
    const double share = species[k].fraction * static_cast<double>(count);
    counts[k] = static_cast<std::size_t>(std::floor(share));
    remainder[k] = share - static_cast<double>(counts[k]);
    given += counts[k];
  }
  std::vector<std::size_t> order(species.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t l, std::size_t r) { return remainder[l] > remainder[r]; });
  for (std::size_t k = 0; given < count; k = (k + 1) % order.size(), ++given) ++counts[order[k]];
  while (given > count) {  // fractions summing a rounding above 1
    for (std::size_t k = species.size(); k-- > 0 && given > count;)
      if (counts[k] > 0) --counts[k], --given;
  }
  return counts;
}

ParticleSet generate_packing(const PackingSpec& spec, const Box& box, double floor, const OverlapTest& overlap) {
  if (!spec.file.empty()) {
    if (spec.species.empty()) return import_packing(spec.file, spec.density, box);
    std::vector<double> densities(spec.species.size());
    for (std::size_t k = 0; k < densities.size(); ++k) densities[k] = spec.species[k].density;
    return import_packing(spec.file, densities, box);
  }
  std::vector<Candidate> drawn = draw_particles(spec);
  const std::vector<SpeciesSpec> species = species_of(spec);
  ParticleSet particles;
  if (drawn.empty()) return particles;
  Random random(spec.seed ^ 0x5eed5eed5eed5eedULL);

  double total_volume = 0.0;
  double largest = 0.0;
  for (const auto& particle : drawn) {
    total_volume += ellipsoid_volume(particle.axes);
    largest = std::max(largest, particle.bounding);
  }
  double height = std::max(total_volume / (spec.insertion_fraction * box.lx * box.ly), 2.5 * largest);

  std::vector<std::size_t> order(drawn.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t l, std::size_t r) { return drawn[l].bounding > drawn[r].bounding; });

  InsertionGrid grid(box, 2.0 * largest);
  constexpr int kAttempts = 400;
  for (std::size_t index : order) {
    Candidate& particle = drawn[index];
    for (int attempt = 0;; ++attempt) {
      if (attempt > 0 && attempt % kAttempts == 0) height *= 1.05;  // region too full: extend it upward
      if (attempt > 200 * kAttempts)
        throw std::runtime_error("packing generation: cannot place particle " + std::to_string(index));
      const double low = floor + particle.bounding;
      const double high = std::max(low, floor + height - particle.bounding);
      const Eigen::Vector3d centre(random.uniform(0.0, box.lx), random.uniform(0.0, box.ly), random.uniform(low, high));
      const bool blocked = grid.any_neighbour(centre, [&](std::size_t other) {
        const Candidate& placed = drawn[other];
        Eigen::Vector3d d = placed.centre - centre;
        d.x() -= box.lx * std::round(d.x() / box.lx);
        d.y() -= box.ly * std::round(d.y() / box.ly);
        const double reach = particle.bounding + placed.bounding;
        if (d.squaredNorm() >= reach * reach) return false;
        if (!overlap) return true;
        return overlap(particle.axes, centre, particle.rotation, placed.axes, centre + d, placed.rotation);
      });
      if (blocked) continue;
      particle.centre = centre;
      grid.insert(index, centre);
      break;
    }
  }
  // Ids in spatial order (z layers, then y rows, then x), so that neighbours sit close in memory.
  const double layer = 2.0 * spec.mean_radius;
  const auto cell = [&](const Candidate& c) {
    return std::array<long, 3>{std::lround(std::floor(c.centre.z() / layer)),
                               std::lround(std::floor(c.centre.y() / layer)),
                               std::lround(std::floor(c.centre.x() / layer))};
  };
  std::vector<std::size_t> spatial(drawn.size());
  std::iota(spatial.begin(), spatial.end(), std::size_t{0});
  std::stable_sort(spatial.begin(), spatial.end(),
                   [&](std::size_t l, std::size_t r) { return cell(drawn[l]) < cell(drawn[r]); });
  for (std::size_t rank = 0; rank < spatial.size(); ++rank) {
    const Candidate& particle = drawn[spatial[rank]];
    particles.add(static_cast<std::uint32_t>(rank), particle.axes, species[particle.species].density, particle.centre,
                  particle.rotation, particle.species);
  }
  return particles;
}

OverlapTest ellipsoid_overlap_test(double margin) {
  return
      [margin](const Eigen::Vector3d& axes_a, const Eigen::Vector3d& centre_a, const Eigen::Quaterniond& rotation_a,
               const Eigen::Vector3d& axes_b, const Eigen::Vector3d& centre_b, const Eigen::Quaterniond& rotation_b) {
        const Ellipsoid a(axes_a * (1.0 + margin), Pose{centre_a, rotation_a});
        const Ellipsoid b(axes_b * (1.0 + margin), Pose{centre_b, rotation_b});
        return ellipsoid_contact(a, b).status != NarrowPhaseStatus::separated;  // failed counts as overlap
      };
}

}  // namespace ellc::scenario
