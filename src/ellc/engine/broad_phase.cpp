#include "ellc/engine/broad_phase.hpp"

#include "ellc/assert.hpp"
#include "ellc/contact/contact_energy.hpp"
#include "ellc/engine/invariants.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

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

// Distinct neighbour offsets along one axis (wrapping when periodic, clipped otherwise). Cells
// span the largest reach 2 R_max + skin, so partners lie in the 3³ cells around a particle's own.
// (5³ half-size cells, scanning 58 % of that volume, measured no faster on a dense 10⁴ packing.)
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
  ELLC_ASSERT(invariants::positions_in_box(particles, box), "wrap_positions left a particle outside [0, lx) x [0, ly)");
}

std::vector<PairSlot> find_candidate_pairs(const ParticleSet& particles, const Box& box, double skin, bool parallel) {
  std::vector<PairSlot> pairs;
  find_candidate_pairs(particles, box, skin, parallel, pairs);
  return pairs;
}

void find_candidate_pairs(const ParticleSet& particles, const Box& box, double skin, bool parallel,
                          std::vector<PairSlot>& pairs) {
  ELLC_ASSERT(invariants::positions_in_box(particles, box), "find_candidate_pairs needs x, y wrapped into the box");
  const std::size_t count = particles.size();
  if (count < 2) {
    pairs.clear();
    return;
  }
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

  // The list must come out sorted by key (id_i, id_j). Visiting the particles in id order and
  // sorting each one's few partners by id gives that order directly: contiguous blocks of the
  // id order go to the threads and are joined in block order, so the list is the same for any
  // number of threads, and no global sort of all candidates is needed.
  const auto& id = particles.id;
  std::vector<std::uint32_t> by_id(count);
  std::iota(by_id.begin(), by_id.end(), std::uint32_t{0});
  std::sort(by_id.begin(), by_id.end(), [&id](std::uint32_t l, std::uint32_t r) { return id[l] < id[r]; });

  struct Candidate {  // small: sorted and joined before the (large) pair slots are made
    PairKey key;
    std::uint32_t i, j;
    Eigen::Vector3d shift;
  };
  int blocks = 1;
#ifdef _OPENMP
  if (parallel) blocks = omp_get_max_threads();
#endif
  std::vector<std::vector<Candidate>> found(static_cast<std::size_t>(blocks));
  // What the distance test reads, copied in cell order: a neighbour cell is then one contiguous
  // run of memory instead of scattered reads through three arrays.
  struct Sphere {
    Eigen::Vector3d centre;
    double radius;
    std::uint32_t id;
    std::uint32_t slot;
  };
  std::vector<Sphere> in_cell_order(count);
  for (std::size_t k = 0; k < count; ++k) {
    const std::uint32_t slot = sorted[k];
    in_cell_order[k] = {particles.position[slot], particles.bounding_radius[slot], id[slot], slot};
  }

#pragma omp parallel for schedule(static, 1) if (parallel)
  for (int block = 0; block < blocks; ++block) {
    auto& out = found[static_cast<std::size_t>(block)];
    out.reserve(8 * count / static_cast<std::size_t>(blocks));
    const std::size_t first = count * static_cast<std::size_t>(block) / static_cast<std::size_t>(blocks);
    const std::size_t last = count * static_cast<std::size_t>(block + 1) / static_cast<std::size_t>(blocks);
    for (std::size_t rank = first; rank < last; ++rank) {
      const std::uint32_t p = by_id[rank];
      const Eigen::Vector3d centre = particles.position[p];
      const double radius_p = particles.bounding_radius[p];
      const std::uint32_t id_p = id[p];
      const int cell = cell_of[p];
      const int ix = cell % grid.nx;
      const int iy = (cell / grid.nx) % grid.ny;
      const int iz = cell / (grid.nx * grid.ny);
      int nxs[3], nys[3], nzs[3];
      const int cx = neighbour_cells(ix, grid.nx, true, nxs);
      const int cy = neighbour_cells(iy, grid.ny, true, nys);
      const int cz = neighbour_cells(iz, grid.nz, false, nzs);
      const std::size_t partners_begin = out.size();
      for (int kz = 0; kz < cz; ++kz)
        for (int ky = 0; ky < cy; ++ky)
          for (int kx = 0; kx < cx; ++kx) {
            const int other = grid.index(nxs[kx], nys[ky], nzs[kz]);
            for (int b = cell_start[other]; b < cell_start[other + 1]; ++b) {
              const Sphere& q = in_cell_order[static_cast<std::size_t>(b)];
              if (q.id <= id_p) continue;  // each unordered pair once, from its smaller id
              const Eigen::Vector3d raw = q.centre - centre;
              const Eigen::Vector3d d(minimum_image(raw.x(), box.lx), minimum_image(raw.y(), box.ly), raw.z());
              const double reach = radius_p + q.radius + skin;
              if (d.squaredNorm() >= reach * reach) continue;
              out.push_back({pair_key(id_p, q.id), p, q.slot, d - raw});  // shift: image offset of q seen from p
            }
          }
      std::sort(out.begin() + static_cast<std::ptrdiff_t>(partners_begin), out.end(),
                [](const Candidate& l, const Candidate& r) { return l.key < r.key; });
    }
  }
  std::vector<std::size_t> offset(found.size() + 1, 0);
  for (std::size_t block = 0; block < found.size(); ++block) offset[block + 1] = offset[block] + found[block].size();
  // Resizing a list of about the same length constructs (and zero-fills) nothing serially; every
  // slot is overwritten below, in parallel.
  pairs.resize(offset.back());
#pragma omp parallel for schedule(static, 1) if (parallel)
  for (int block = 0; block < blocks; ++block) {
    const auto& part = found[static_cast<std::size_t>(block)];
    for (std::size_t k = 0; k < part.size(); ++k) {
      PairSlot& pair = pairs[offset[static_cast<std::size_t>(block)] + k];
      pair = PairSlot{};
      pair.key = part[k].key;
      pair.i = part[k].i;
      pair.j = part[k].j;
      pair.shift = part[k].shift;
    }
  }
  ELLC_ASSERT(invariants::valid_pair_list(pairs, particles), "pairs not sorted by key, or slots/ids inconsistent");
}

double carry_over_history(std::vector<PairSlot>& previous, std::vector<PairSlot>& next) noexcept {
  ELLC_ASSERT(invariants::keys_sorted(previous) && invariants::keys_sorted(next), "both lists must be sorted by key");
  double released_work = 0.0;
  std::size_t n = 0;
  for (auto& old_pair : previous) {
    // Separated pairs keep their last separating axis: it spares the next narrow phase a cold start.
    const bool active = old_pair.history.active();
    if (!active && !old_pair.cache.constants_cached && old_pair.history.warm_valid == 0.0) continue;
    while (n < next.size() && next[n].key < old_pair.key) ++n;
    if (n < next.size() && next[n].key == old_pair.key) {
      next[n].history = old_pair.history;
      next[n].cache = old_pair.cache;
    } else if (active) {
      // Plastic work and the spring's energy, both dissipated (the pair left the list while touching).
      released_work += plastic_work(old_pair.cache.constants, old_pair.history.max_overlap) +
                       old_pair.history.spring_energy();
    }
  }
  return released_work;
}

}  // namespace ellc::engine
