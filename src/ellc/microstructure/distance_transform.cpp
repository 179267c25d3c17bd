#include "ellc/microstructure/distance_transform.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ellc::microstructure {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// One exact 1-D pass: d(p) = min_q f(q) + (h (p − q))², over n samples (Felzenszwalb &
// Huttenlocher's lower envelope of parabolas). A periodic line is unrolled three times; the
// middle copy then sees every image within half a period, which holds the nearest one.
struct LinePass {
  std::vector<double> f;
  std::vector<double> d;
  std::vector<int> v;
  std::vector<double> z;

  // `in`: the line, contiguous; `out`: the grid, every `stride`-th value.
  void run(const double* in, double* out, int n, std::size_t stride, double h, bool periodic) {
    const int copies = periodic && n > 1 ? 3 : 1;
    const int m = n * copies;
    f.resize(static_cast<std::size_t>(m));
    d.resize(static_cast<std::size_t>(m));
    v.resize(static_cast<std::size_t>(m));
    z.resize(static_cast<std::size_t>(m) + 1);
    for (int k = 0; k < m; ++k) f[static_cast<std::size_t>(k)] = in[k % n];
    const double h2 = h * h;
    int hull = -1;
    for (int q = 0; q < m; ++q) {
      const double fq = f[static_cast<std::size_t>(q)];
      if (fq == kInfinity) continue;
      const double dq = static_cast<double>(q);
      while (hull >= 0) {
        const int p = v[static_cast<std::size_t>(hull)];
        const double dp = static_cast<double>(p);
        const double s =
            ((fq + h2 * dq * dq) - (f[static_cast<std::size_t>(p)] + h2 * dp * dp)) / (2.0 * h2 * (dq - dp));
        if (s <= z[static_cast<std::size_t>(hull)]) {
          --hull;
          continue;
        }
        ++hull;
        v[static_cast<std::size_t>(hull)] = q;
        z[static_cast<std::size_t>(hull)] = s;
        z[static_cast<std::size_t>(hull) + 1] = kInfinity;
        break;
      }
      if (hull < 0) {
        hull = 0;
        v[0] = q;
        z[0] = -kInfinity;
        z[1] = kInfinity;
      }
    }
    const int first = copies == 3 ? n : 0;
    if (hull < 0) {
      for (int p = 0; p < n; ++p) out[static_cast<std::size_t>(p) * stride] = kInfinity;
      return;
    }
    int k = 0;
    for (int p = first; p < first + n; ++p) {
      const double dp = static_cast<double>(p);
      while (z[static_cast<std::size_t>(k) + 1] < dp) ++k;
      const int q = v[static_cast<std::size_t>(k)];
      const double dq = dp - static_cast<double>(q);
      d[static_cast<std::size_t>(p - first)] = h2 * dq * dq + f[static_cast<std::size_t>(q)];
    }
    for (int p = 0; p < n; ++p) out[static_cast<std::size_t>(p) * stride] = d[static_cast<std::size_t>(p)];
  }
};

}  // namespace

std::vector<double> squared_distance_transform(const std::vector<std::uint8_t>& feature, const VoxelGrid& grid) {
  const std::size_t nx = static_cast<std::size_t>(grid.shape[0]);
  const std::size_t ny = static_cast<std::size_t>(grid.shape[1]);
  const std::size_t nz = static_cast<std::size_t>(grid.shape[2]);
  std::vector<double> distance(grid.size());
  for (std::size_t k = 0; k < distance.size(); ++k) distance[k] = feature[k] != 0 ? 0.0 : kInfinity;
  const std::array<std::size_t, 3> stride{1, nx, nx * ny};
  // Axis by axis, each line independently (in place: a line is copied into the pass first).
  for (int axis = 0; axis < 3; ++axis) {
    const std::size_t a = static_cast<std::size_t>(axis);
    const std::size_t n = a == 0 ? nx : (a == 1 ? ny : nz);
    const std::size_t lines = grid.size() / n;
#pragma omp parallel if (grid.size() >= (std::size_t{1} << 16))
    {
      LinePass pass;
      std::vector<double> line(n);
#pragma omp for schedule(static)
      for (std::size_t l = 0; l < lines; ++l) {
        // The start of line l: the index with the axis coordinate 0.
        std::size_t start = 0;
        if (a == 0)
          start = l * nx;
        else if (a == 1)
          start = (l % nx) + (l / nx) * nx * ny;
        else
          start = l;
        for (std::size_t p = 0; p < n; ++p) line[p] = distance[start + p * stride[a]];
        pass.run(line.data(), distance.data() + start, static_cast<int>(n), stride[a], grid.spacing[axis],
                 grid.periodic[a]);
      }
    }
  }
  return distance;
}

PoreSizeDistribution continuous_pore_size_distribution(const VoxelGrid& grid, int max_radii) {
  PoreSizeDistribution psd;
  const std::vector<double> to_solid = squared_distance_transform(grid.solid, grid);
  std::size_t pore_count = 0;
  double largest2 = 0.0;
  for (std::size_t k = 0; k < to_solid.size(); ++k)
    if (grid.solid[k] == 0) {
      ++pore_count;
      if (std::isfinite(to_solid[k])) largest2 = std::max(largest2, to_solid[k]);
    }
  if (pore_count == 0) return psd;
  psd.largest_radius = std::sqrt(largest2);
  const double step_min = grid.spacing.minCoeff();
  const int steps = std::max(1, static_cast<int>(std::floor(psd.largest_radius / step_min)));
  const int count = std::min(steps, std::max(2, max_radii));
  std::vector<std::uint8_t> centres(grid.size());
  for (int k = 1; k <= count; ++k) {
    const double r = psd.largest_radius * static_cast<double>(k) / static_cast<double>(count);
    // Centres of the spheres of radius r that fit: at least r from every solid voxel centre.
    const double r2 = r * r * (1.0 - 1e-12);
    for (std::size_t v = 0; v < centres.size(); ++v) centres[v] = grid.solid[v] == 0 && to_solid[v] >= r2 ? 1 : 0;
    const std::vector<double> to_centre = squared_distance_transform(centres, grid);
    std::size_t covered = 0;
    const double reach = r * r * (1.0 + 1e-12);
    for (std::size_t v = 0; v < centres.size(); ++v) covered += grid.solid[v] == 0 && to_centre[v] <= reach ? 1U : 0U;
    psd.radius.push_back(r);
    psd.cumulative_fraction.push_back(static_cast<double>(covered) / static_cast<double>(pore_count));
  }
  // No sphere larger than the largest inscribed one fits: V = 0 one voxel beyond it.
  psd.radius.push_back(psd.largest_radius + step_min);
  psd.cumulative_fraction.push_back(0.0);
  // Below the first radius every pore voxel is covered (V → 1 as r → 0).
  psd.radius.insert(psd.radius.begin(), 0.0);
  psd.cumulative_fraction.insert(psd.cumulative_fraction.begin(), 1.0);
  psd.density.assign(psd.radius.size(), 0.0);
  for (std::size_t k = 1; k < psd.radius.size(); ++k)
    psd.density[k] =
        (psd.cumulative_fraction[k - 1] - psd.cumulative_fraction[k]) / (psd.radius[k] - psd.radius[k - 1]);
  for (std::size_t k = 1; k < psd.radius.size(); ++k)
    if (psd.cumulative_fraction[k] <= 0.5) {
      const double v0 = psd.cumulative_fraction[k - 1];
      const double v1 = psd.cumulative_fraction[k];
      psd.median_radius = psd.radius[k - 1] + (v0 - 0.5) / (v0 - v1) * (psd.radius[k] - psd.radius[k - 1]);
      break;
    }
  return psd;
}

}  // namespace ellc::microstructure
