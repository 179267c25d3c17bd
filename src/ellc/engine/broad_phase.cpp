#include "ellc/engine/broad_phase.hpp"

#include "ellc/engine/contact_force.hpp"

#include <algorithm>
#include <cmath>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace ellc::engine {

namespace {

struct CellGrid {
  int nx = 1, ny = 1, nz = 1;
  double cell_x = 1.0, cell_y = 1.0, cell_z = 1.0, z_min = 0.0;

  [[nodiscard]] int index(int ix, int iy, int iz) const noexcept { return (iz * ny + iy) * nx + ix; }
  [[nodiscard]] int count() const noexcept { return nx * ny * nz; }
  [[nodiscard]] int clamp_cell(double coordinate, double origin, double size, int n) const noexcept {
    const int cell = static_cast<int>(std::floor((coordinate - origin) / size));
    return std::clamp(cell, 0, n - 1);
  }
  [[nodiscard]] int cell_of(const Eigen::Vector3d& x) const noexcept {
    return index(clamp_cell(x.x(), 0.0, cell_x, nx), clamp_cell(x.y(), 0.0, cell_y, ny),
                 clamp_cell(x.z(), z_min, cell_z, nz));
  }
};

CellGrid make_grid(const ParticleSet& particles, const Box& box, double cell_size) {
  CellGrid grid;
  double z_min = particles.position.empty() ? 0.0 : particles.position[0].z();
  double z_max = z_min;
  for (const auto& x : particles.position) {
    z_min = std::min(z_min, x.z());
    z_max = std::max(z_max, x.z());
  }
  grid.nx = std::max(1, static_cast<int>(box.lx / cell_size));
  grid.ny = std::max(1, static_cast<int>(box.ly / cell_size));
  grid.nz = std::max(1, static_cast<int>((z_max - z_min) / cell_size) + 1);
  grid.cell_x = box.lx / grid.nx;
  grid.cell_y = box.ly / grid.ny;
  grid.cell_z = cell_size;
  grid.z_min = z_min;
  return grid;
}

// Distinct neighbour offsets along one axis (wrapping when periodic, clipped otherwise).
int neighbour_cells(int cell, int n, bool periodic, int out[3]) {
  int count = 0;
  for (int offset = -1; offset <= 1; ++offset) {
    int other = cell + offset;
    if (periodic) {
      other = (other % n + n) % n;
    } else if (other < 0 || other >= n) {
      continue;
    }
    if (std::find(out, out + count, other) == out + count) out[count++] = other;
  }
  return count;
}

// The periodic image of a separation closest to zero (|d| ≤ L/2 for |d| < 3L/2).
double minimum_image(double d, double length) noexcept {
  if (d > 0.5 * length) return d - length;
  if (d < -0.5 * length) return d + length;
  return d;
}

}  // namespace

void wrap_positions(ParticleSet& particles, const Box& box) noexcept {
  for (auto& x : particles.position) {
    x.x() -= box.lx * std::floor(x.x() / box.lx);
    x.y() -= box.ly * std::floor(x.y() / box.ly);
    if (x.x() >= box.lx) x.x() = 0.0;  // −tiny wraps to lx after rounding
    if (x.y() >= box.ly) x.y() = 0.0;
  }
}

std::vector<PairSlot> find_candidate_pairs(const ParticleSet& particles, const Box& box, double skin, bool parallel) {
  const std::size_t count = particles.size();
  if (count < 2) return {};
  const double max_radius = *std::max_element(particles.bounding_radius.begin(), particles.bounding_radius.end());
  const CellGrid grid = make_grid(particles, box, 2.0 * max_radius + skin);

  // Counting sort of the slots by cell.
  std::vector<int> cell_of(count);
  std::vector<int> cell_start(static_cast<std::size_t>(grid.count()) + 1, 0);
  for (std::size_t slot = 0; slot < count; ++slot) {
    cell_of[slot] = grid.cell_of(particles.position[slot]);
    ++cell_start[static_cast<std::size_t>(cell_of[slot]) + 1];
  }
  for (int cell = 0; cell < grid.count(); ++cell) cell_start[cell + 1] += cell_start[cell];
  std::vector<std::uint32_t> sorted(count);
  {
    std::vector<int> fill(cell_start.begin(), cell_start.end() - 1);
    for (std::size_t slot = 0; slot < count; ++slot) sorted[fill[cell_of[slot]]++] = static_cast<std::uint32_t>(slot);
  }

  int threads = 1;
#ifdef _OPENMP
  threads = omp_get_max_threads();
#endif
  struct Candidate {  // small: sorted before the (large) pair slots are made
    PairKey key;
    std::uint32_t i, j;
    Eigen::Vector3d shift;
  };
  std::vector<std::vector<Candidate>> found(static_cast<std::size_t>(threads));
  const auto& x = particles.position;
  const auto& radius = particles.bounding_radius;

#pragma omp parallel for schedule(dynamic, 16) if (parallel)
  for (int cell = 0; cell < grid.count(); ++cell) {
    int thread = 0;
#ifdef _OPENMP
    thread = omp_get_thread_num();
#endif
    auto& out = found[static_cast<std::size_t>(thread)];
    const int ix = cell % grid.nx;
    const int iy = (cell / grid.nx) % grid.ny;
    const int iz = cell / (grid.nx * grid.ny);
    int nxs[3], nys[3], nzs[3];
    const int cx = neighbour_cells(ix, grid.nx, true, nxs);
    const int cy = neighbour_cells(iy, grid.ny, true, nys);
    const int cz = neighbour_cells(iz, grid.nz, false, nzs);
    for (int a = cell_start[cell]; a < cell_start[cell + 1]; ++a) {
      const std::uint32_t p = sorted[a];
      for (int kz = 0; kz < cz; ++kz)
        for (int ky = 0; ky < cy; ++ky)
          for (int kx = 0; kx < cx; ++kx) {
            const int other = grid.index(nxs[kx], nys[ky], nzs[kz]);
            for (int b = cell_start[other]; b < cell_start[other + 1]; ++b) {
              const std::uint32_t q = sorted[b];
              if (q <= p) continue;  // each unordered pair once
              const Eigen::Vector3d raw = x[q] - x[p];
              const Eigen::Vector3d d(minimum_image(raw.x(), box.lx), minimum_image(raw.y(), box.ly), raw.z());
              const double reach = radius[p] + radius[q] + skin;
              if (d.squaredNorm() >= reach * reach) continue;
              Candidate pair;
              const Eigen::Vector3d shift = d - raw;  // image offset for q seen from p
              if (particles.id[p] < particles.id[q]) {
                pair.i = p;
                pair.j = q;
                pair.shift = shift;
              } else {
                pair.i = q;
                pair.j = p;
                pair.shift = -shift;
              }
              pair.key = pair_key(particles.id[pair.i], particles.id[pair.j]);
              out.push_back(pair);
            }
          }
    }
  }
  std::vector<Candidate> all;
  for (auto& part : found) all.insert(all.end(), part.begin(), part.end());
  std::sort(all.begin(), all.end(), [](const Candidate& l, const Candidate& r) { return l.key < r.key; });
  std::vector<PairSlot> pairs(all.size());
  for (std::size_t index = 0; index < all.size(); ++index) {
    pairs[index].key = all[index].key;
    pairs[index].i = all[index].i;
    pairs[index].j = all[index].j;
    pairs[index].shift = all[index].shift;
  }
  return pairs;
}

double carry_over_history(std::vector<PairSlot>& previous, std::vector<PairSlot>& next) noexcept {
  double released_work = 0.0;
  std::size_t n = 0;
  for (auto& old_pair : previous) {
    // Separated pairs keep their last separating axis: it spares the next narrow phase a cold start.
    if (!old_pair.history.active && !old_pair.history.constants_cached && !old_pair.history.warm_start.valid) continue;
    while (n < next.size() && next[n].key < old_pair.key) ++n;
    if (n < next.size() && next[n].key == old_pair.key) {
      next[n].history = old_pair.history;
    } else if (old_pair.history.active) {
      released_work += plastic_work(old_pair.history.constants, old_pair.history.max_overlap);
    }
  }
  return released_work;
}

}  // namespace ellc::engine
