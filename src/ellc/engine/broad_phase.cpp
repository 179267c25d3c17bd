#include "ellc/engine/broad_phase.hpp"

#include "ellc/assert.hpp"
#include "ellc/contact/contact_energy.hpp"
#include "ellc/engine/invariants.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <utility>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace ellc::engine {

namespace {

// A sparse cell grid: only occupied cells exist (a hash table of cell keys → runs of the sorted
// slots), so memory follows the particles, not the box. Cell coordinates are 64-bit and at most
// kMaxCellsPerAxis per axis (wider cells when the box is wider: more distance tests, never a
// missed pair), so no count overflows for any box or particle size (issue 19: a dense grid of a
// 4·10⁵ µm box took 3.9 GB, and an `int` cell count overflowed at mean_radius = 1e-4).
constexpr std::int64_t kMaxCellsPerAxis = std::int64_t{1} << 21;  // three coordinates fit a 64-bit key

struct CellGrid {
  std::int64_t nx = 1, ny = 1, nz = 1;
  double cell_x = 1.0, cell_y = 1.0, cell_z = 1.0, z_min = 0.0;

  [[nodiscard]] static std::uint64_t key(std::int64_t ix, std::int64_t iy, std::int64_t iz) noexcept {
    return (static_cast<std::uint64_t>(iz) << 42U) | (static_cast<std::uint64_t>(iy) << 21U) |
           static_cast<std::uint64_t>(ix);
  }
  // The cell coordinates of a key (key's inverse).
  [[nodiscard]] static std::array<std::int64_t, 3> coordinates(std::uint64_t key) noexcept {
    constexpr std::uint64_t kAxisMask = (std::uint64_t{1} << 21U) - 1U;
    return {static_cast<std::int64_t>(key & kAxisMask), static_cast<std::int64_t>((key >> 21U) & kAxisMask),
            static_cast<std::int64_t>(key >> 42U)};
  }
  [[nodiscard]] static std::int64_t clamp_cell(double coordinate, double origin, double size, std::int64_t n) noexcept {
    const double cell = std::floor((coordinate - origin) / size);
    if (!(cell > 0.0)) return 0;  // also NaN
    return cell >= static_cast<double>(n - 1) ? n - 1 : static_cast<std::int64_t>(cell);
  }
  [[nodiscard]] std::array<std::int64_t, 3> cell_of(const Eigen::Vector3d& x) const noexcept {
    return {clamp_cell(x.x(), 0.0, cell_x, nx), clamp_cell(x.y(), 0.0, cell_y, ny),
            clamp_cell(x.z(), z_min, cell_z, nz)};
  }
};

// Cells along an extent: as many as fit cell_size (at least 1, at most kMaxCellsPerAxis).
std::int64_t cells_along(double extent, double cell_size) noexcept {
  const double fit = std::floor(extent / cell_size);
  if (!(fit >= 1.0)) return 1;
  return fit >= static_cast<double>(kMaxCellsPerAxis) ? kMaxCellsPerAxis : static_cast<std::int64_t>(fit);
}

CellGrid make_grid(const ParticleSet& particles, const Box& box, double cell_size) {
  CellGrid grid;
  double z_min = particles.position.empty() ? 0.0 : particles.position[0].z();
  double z_max = z_min;
  for (const auto& x : particles.position) {
    z_min = std::min(z_min, x.z());
    z_max = std::max(z_max, x.z());
  }
  grid.nx = cells_along(box.lx, cell_size);
  grid.ny = cells_along(box.ly, cell_size);
  grid.cell_x = box.lx / static_cast<double>(grid.nx);
  grid.cell_y = box.ly / static_cast<double>(grid.ny);
  // z is open: cells of cell_size from the lowest centre, wider if the column needs more than
  // the cap (cells at least cell_size wide always hold all partners in the 3 around).
  const double z_cells = std::floor((z_max - z_min) / cell_size) + 1.0;
  grid.nz = z_cells < static_cast<double>(kMaxCellsPerAxis) ? static_cast<std::int64_t>(z_cells) : kMaxCellsPerAxis;
  grid.cell_z = grid.nz < kMaxCellsPerAxis
                    ? cell_size
                    : std::max(cell_size, (z_max - z_min) / static_cast<double>(kMaxCellsPerAxis - 1));
  grid.z_min = z_min;
  return grid;
}

// The occupied cells: the slots sorted by cell key, each cell one run of that order, found
// through an open-addressing hash table (linear probing, at most half full).
class OccupiedCells {
 public:
  // `sorted`: the slots by cell key, and by id within a cell.
  OccupiedCells(const std::vector<std::uint64_t>& key_of_slot, const std::vector<std::uint32_t>& id,
                std::vector<std::uint32_t>& sorted) {
    const std::size_t count = key_of_slot.size();
    struct Entry {
      std::uint64_t key;
      std::uint32_t id, slot;
    };
    std::vector<Entry> by_cell(count);
    for (std::size_t slot = 0; slot < count; ++slot)
      by_cell[slot] = {key_of_slot[slot], id[slot], static_cast<std::uint32_t>(slot)};
    std::sort(by_cell.begin(), by_cell.end(),
              [](const Entry& l, const Entry& r) { return l.key != r.key ? l.key < r.key : l.id < r.id; });
    sorted.resize(count);
    cell_of_slot_.resize(count);
    for (std::size_t k = 0; k < count; ++k) {
      sorted[k] = by_cell[k].slot;
      if (k == 0 || by_cell[k].key != by_cell[k - 1].key) {
        keys_.push_back(by_cell[k].key);
        begin_.push_back(k);
      }
      cell_of_slot_[by_cell[k].slot] = static_cast<std::uint32_t>(keys_.size() - 1);
    }
    begin_.push_back(count);
    std::size_t capacity = 16;
    shift_ = 60;
    while (capacity < 2 * keys_.size()) {
      capacity *= 2;
      --shift_;
    }
    mask_ = capacity - 1;
    table_.assign(capacity, kEmpty);
    for (std::size_t cell = 0; cell < keys_.size(); ++cell) {
      std::size_t at = bucket(keys_[cell]);
      while (table_[at] != kEmpty) at = (at + 1) & mask_;
      table_[at] = cell;
    }
  }
  [[nodiscard]] std::size_t size() const noexcept { return keys_.size(); }
  [[nodiscard]] std::uint64_t key(std::size_t cell) const noexcept { return keys_[cell]; }
  [[nodiscard]] std::uint32_t cell_of_slot(std::size_t slot) const noexcept { return cell_of_slot_[slot]; }
  // The run [first, last) of the sorted slots in the cell with this key (empty if unoccupied).
  [[nodiscard]] std::pair<std::size_t, std::size_t> run(std::uint64_t key) const noexcept {
    for (std::size_t at = bucket(key); table_[at] != kEmpty; at = (at + 1) & mask_)
      if (keys_[table_[at]] == key) return {begin_[table_[at]], begin_[table_[at] + 1]};
    return {0, 0};
  }

 private:
  static constexpr std::size_t kEmpty = ~std::size_t{0};
  [[nodiscard]] std::size_t bucket(std::uint64_t key) const noexcept {
    return static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ULL) >> shift_);  // Fibonacci hashing
  }
  std::vector<std::uint64_t> keys_;
  std::vector<std::size_t> begin_;
  std::vector<std::uint32_t> cell_of_slot_;  // index into keys_ of each particle slot
  std::vector<std::size_t> table_;
  std::size_t mask_ = 0;
  unsigned shift_ = 60;  // 64 − log2(capacity)
};

// Distinct neighbour offsets along one axis (wrapping when periodic, clipped otherwise). Cells
// span the largest reach 2 R_max + skin, so partners lie in the 3³ cells around a particle's own.
// (5³ half-size cells, scanning 58 % of that volume, measured no faster on a dense 10⁴ packing.)
int neighbour_cells(std::int64_t cell, std::int64_t n, bool periodic, std::int64_t out[3]) {
  int count = 0;
  for (std::int64_t offset = -1; offset <= 1; ++offset) {
    std::int64_t other = cell + offset;
    if (periodic) {
      other = (other % n + n) % n;
    } else if (other < 0 || other >= n) {
      continue;
    }
    if (std::find(out, out + count, other) == out + count) out[count++] = other;
  }
  return count;
}

// For every occupied cell, the runs of the cell-sorted slots in the 3³ cells around it, looked up
// once per cell instead of once per particle (a cell holds ~10 particles of a dense packing).
// Partners are sorted by key afterwards, so the order in which the runs are visited does not
// change the list.
struct NeighbourRuns {
  std::vector<std::uint32_t> begin;                           // per cell, into runs; size cells + 1
  std::vector<std::pair<std::uint32_t, std::uint32_t>> runs;  // [first, last) of the sorted slots
};

NeighbourRuns neighbour_runs(const OccupiedCells& cells, const CellGrid& grid) {
  NeighbourRuns result;
  result.begin.reserve(cells.size() + 1);
  result.runs.reserve(9 * cells.size());
  for (std::size_t cell = 0; cell < cells.size(); ++cell) {
    result.begin.push_back(static_cast<std::uint32_t>(result.runs.size()));
    const auto [ix, iy, iz] = CellGrid::coordinates(cells.key(cell));
    std::int64_t nxs[3], nys[3], nzs[3];
    const int cx = neighbour_cells(ix, grid.nx, true, nxs);
    const int cy = neighbour_cells(iy, grid.ny, true, nys);
    const int cz = neighbour_cells(iz, grid.nz, false, nzs);
    for (int kz = 0; kz < cz; ++kz)
      for (int ky = 0; ky < cy; ++ky)
        for (int kx = 0; kx < cx; ++kx) {
          const auto [first, last] = cells.run(CellGrid::key(nxs[kx], nys[ky], nzs[kz]));
          if (first < last)
            result.runs.emplace_back(static_cast<std::uint32_t>(first), static_cast<std::uint32_t>(last));
        }
  }
  result.begin.push_back(static_cast<std::uint32_t>(result.runs.size()));
  return result;
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

std::vector<PairSlot> find_candidate_pairs(const ParticleSet& particles, const Box& box, double skin, int threads) {
  std::vector<PairSlot> pairs;
  find_candidate_pairs(particles, box, skin, threads, pairs);
  return pairs;
}

void find_candidate_pairs(const ParticleSet& particles, const Box& box, double skin, int threads,
                          std::vector<PairSlot>& pairs) {
  ELLC_ASSERT(invariants::positions_in_box(particles, box), "find_candidate_pairs needs x, y wrapped into the box");
  const std::size_t count = particles.size();
  if (count < 2) {
    pairs.clear();
    return;
  }
  const double max_radius = *std::max_element(particles.bounding_radius.begin(), particles.bounding_radius.end());
  const CellGrid grid = make_grid(particles, box, 2.0 * max_radius + skin);

  // The slots sorted by cell, and the occupied cells.
  std::vector<std::uint64_t> key_of_slot(count);
  for (std::size_t slot = 0; slot < count; ++slot) {
    const auto [ix, iy, iz] = grid.cell_of(particles.position[slot]);
    key_of_slot[slot] = CellGrid::key(ix, iy, iz);
  }
  std::vector<std::uint32_t> sorted;
  const OccupiedCells cells(key_of_slot, particles.id, sorted);
  const NeighbourRuns around = neighbour_runs(cells, grid);

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
  const bool parallel = threads > 1;
  const int blocks = std::max(threads, 1);  // one id range per thread
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

#pragma omp parallel for schedule(static, 1) num_threads(blocks) if (parallel)
  for (int block = 0; block < blocks; ++block) {
    auto& out = found[static_cast<std::size_t>(block)];
    std::vector<Candidate> scratch;  // one particle's tested pairs
    out.reserve(8 * count / static_cast<std::size_t>(blocks));
    const std::size_t first = count * static_cast<std::size_t>(block) / static_cast<std::size_t>(blocks);
    const std::size_t last = count * static_cast<std::size_t>(block + 1) / static_cast<std::size_t>(blocks);
    for (std::size_t rank = first; rank < last; ++rank) {
      const std::uint32_t p = by_id[rank];
      const Eigen::Vector3d centre = particles.position[p];
      const double radius_p = particles.bounding_radius[p];
      const std::uint32_t id_p = id[p];
      const std::uint32_t cell = cells.cell_of_slot(p);
      const std::size_t partners_begin = out.size();
      // Each unordered pair once, from its smaller id: a run is sorted by id, so its partners of
      // larger id are its tail, walked from the end. A tested pair is written to the scratch and
      // counted only if within reach, without a branch: which pairs are is data the branch
      // predictor cannot learn (the rebuild of 10⁴ spheres 16 % faster, of ellipsoids 9 %).
      std::size_t bound = 0;
      for (std::uint32_t r = around.begin[cell]; r < around.begin[cell + 1]; ++r)
        bound += around.runs[r].second - around.runs[r].first;
      if (scratch.size() < bound) scratch.resize(bound);
      std::size_t kept = 0;
      for (std::uint32_t r = around.begin[cell]; r < around.begin[cell + 1]; ++r) {
        for (std::size_t b = around.runs[r].second; b > around.runs[r].first && in_cell_order[b - 1].id > id_p; --b) {
          const Sphere& q = in_cell_order[b - 1];
          const Eigen::Vector3d raw = q.centre - centre;
          const Eigen::Vector3d d(minimum_image(raw.x(), box.lx), minimum_image(raw.y(), box.ly), raw.z());
          const double reach = radius_p + q.radius + skin;
          scratch[kept] = {pair_key(id_p, q.id), p, q.slot, d - raw};  // shift: image offset of q seen from p
          kept += static_cast<std::size_t>(!(d.squaredNorm() >= reach * reach));  // NaN kept, as before
        }
      }
      out.insert(out.end(), scratch.begin(), scratch.begin() + static_cast<std::ptrdiff_t>(kept));
      std::sort(out.begin() + static_cast<std::ptrdiff_t>(partners_begin), out.end(),
                [](const Candidate& l, const Candidate& r) { return l.key < r.key; });
    }
  }
  std::vector<std::size_t> offset(found.size() + 1, 0);
  for (std::size_t block = 0; block < found.size(); ++block) offset[block + 1] = offset[block] + found[block].size();
  // Resizing a list of about the same length constructs (and zero-fills) nothing serially; every
  // slot is overwritten below, in parallel.
  pairs.resize(offset.back());
#pragma omp parallel for schedule(static, 1) num_threads(blocks) if (parallel)
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

double carry_over_history(std::vector<PairSlot>& previous, std::vector<PairSlot>& next, int threads) {
  ELLC_ASSERT(invariants::keys_sorted(previous) && invariants::keys_sorted(next), "both lists must be sorted by key");
  // Fixed chunks of the old list, each merged from its first key's place in the new one: the
  // copies are disjoint (keys are unique), and the energy of contacts that left the list is summed
  // afterwards in list order, so the bits do not depend on the thread count (nor differ from a
  // single merge). Such contacts are few; most chunks release nothing.
  constexpr std::size_t kChunk = 4096;
  const std::size_t chunks = (previous.size() + kChunk - 1) / kChunk;
  std::vector<std::vector<double>> released(chunks);
#pragma omp parallel for schedule(dynamic, 1) num_threads(std::max(threads, 1)) if (threads > 1)
  for (std::size_t chunk = 0; chunk < chunks; ++chunk) {
    const std::size_t begin = chunk * kChunk;
    const std::size_t end = std::min(previous.size(), begin + kChunk);
    auto n =
        static_cast<std::size_t>(std::lower_bound(next.begin(), next.end(), previous[begin].key,
                                                  [](const PairSlot& pair, PairKey key) { return pair.key < key; }) -
                                 next.begin());
    for (std::size_t k = begin; k < end; ++k) {
      PairSlot& old_pair = previous[k];
      // Separated pairs keep their last separating axis: it spares the next narrow phase a cold start.
      const bool active = old_pair.history.active();
      if (!active && !old_pair.cache.constants_cached && old_pair.history.warm_valid == 0.0) continue;
      while (n < next.size() && next[n].key < old_pair.key) ++n;
      if (n < next.size() && next[n].key == old_pair.key) {
        next[n].history = old_pair.history;
        next[n].cache = old_pair.cache;
      } else if (active) {
        // Plastic work and the spring's energy, both dissipated (the pair left the list while touching).
        released[chunk].push_back(plastic_work(old_pair.cache.constants, old_pair.history.max_overlap) +
                                  old_pair.history.spring_energy());
      }
    }
  }
  double released_work = 0.0;
  for (const std::vector<double>& values : released)
    for (const double value : values) released_work += value;
  return released_work;
}

}  // namespace ellc::engine
