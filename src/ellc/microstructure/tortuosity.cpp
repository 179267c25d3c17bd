#include "ellc/microstructure/tortuosity.hpp"

#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "ellc/io/input_error.hpp"

namespace ellc::microstructure {

namespace {

constexpr std::array<char, 3> kAxisName{'x', 'y', 'z'};
constexpr std::size_t kParallelVoxels = std::size_t{1} << 16;

double harmonic_mean(double a, double b) noexcept { return a > 0.0 && b > 0.0 ? 2.0 * a * b / (a + b) : 0.0; }

// Neighbour lookup on the grid: along the flow axis the faces are the boundaries; along the others
// the grid wraps where it is periodic and ends (no flux) where it is not.
class Lattice {
 public:
  Lattice(const VoxelGrid& grid, int axis) : grid_(grid), axis_(axis) {
    for (std::size_t b = 0; b < 3; ++b) n_[b] = grid.shape[b];
    stride_ = {1, static_cast<long>(n_[0]), static_cast<long>(n_[0]) * static_cast<long>(n_[1])};
  }
  // Index of the neighbour of (i0, i1, i2) = `at` one step `step` (±1) along `b`, or −1.
  [[nodiscard]] long neighbour(const std::array<int, 3>& at, std::size_t b, int step) const noexcept {
    const int i = at[b] + step;
    long shift = step * stride_[b];
    if (i < 0 || i >= n_[b]) {
      if (static_cast<int>(b) == axis_ || !grid_.periodic[b] || n_[b] < 2) return -1;
      shift = i < 0 ? (n_[b] - 1) * stride_[b] : -(n_[b] - 1) * stride_[b];
    }
    return static_cast<long>(grid_.index(at[0], at[1], at[2])) + shift;
  }
  [[nodiscard]] const std::array<int, 3>& shape() const noexcept { return n_; }

 private:
  const VoxelGrid& grid_;
  int axis_;
  std::array<int, 3> n_{};
  std::array<long, 3> stride_{};
};

// Marks the voxels with D > 0 connected to the face i_axis = face_index.
std::vector<std::uint8_t> reachable_from_face(const Lattice& lattice, const VoxelGrid& grid,
                                              const std::vector<double>& diffusivity, std::size_t axis,
                                              int face_index) {
  std::vector<std::uint8_t> reached(grid.size(), 0);
  std::vector<std::uint32_t> stack;
  const auto& n = lattice.shape();
  for (int i2 = 0; i2 < n[2]; ++i2)
    for (int i1 = 0; i1 < n[1]; ++i1)
      for (int i0 = 0; i0 < n[0]; ++i0) {
        const std::array<int, 3> at{i0, i1, i2};
        if (at[axis] != face_index) continue;
        const std::size_t k = grid.index(i0, i1, i2);
        if (diffusivity[k] > 0.0 && reached[k] == 0) {
          reached[k] = 1;
          stack.push_back(static_cast<std::uint32_t>(k));
        }
      }
  while (!stack.empty()) {
    const std::size_t k = stack.back();
    stack.pop_back();
    const std::size_t layer = static_cast<std::size_t>(n[0]) * static_cast<std::size_t>(n[1]);
    const std::array<int, 3> at{static_cast<int>(k % static_cast<std::size_t>(n[0])),
                                static_cast<int>((k / static_cast<std::size_t>(n[0])) % static_cast<std::size_t>(n[1])),
                                static_cast<int>(k / layer)};
    for (std::size_t b = 0; b < 3; ++b)
      for (const int step : {-1, 1}) {
        const long m = lattice.neighbour(at, b, step);
        if (m < 0) continue;
        const auto mm = static_cast<std::size_t>(m);
        if (reached[mm] == 0 && diffusivity[mm] > 0.0) {
          reached[mm] = 1;
          stack.push_back(static_cast<std::uint32_t>(mm));
        }
      }
  }
  return reached;
}

}  // namespace

DiffusionResult solve_diffusion(const VoxelGrid& grid, const std::vector<double>& diffusivity, int axis, double bulk,
                                const DiffusionOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  DiffusionResult result;
  result.axis = axis;
  const auto a = static_cast<std::size_t>(axis);
  const std::size_t size = grid.size();
  std::size_t open = 0;
  for (const double d : diffusivity) open += d > 0.0 ? 1U : 0U;
  result.porosity = size > 0 ? static_cast<double>(open) / static_cast<double>(size) : 0.0;
  result.tortuosity = std::numeric_limits<double>::infinity();
  const std::string faces = std::string("the faces ") + kAxisName[a] + " = min and " + kAxisName[a] + " = max";
  if (open == 0) {
    result.reason = "no pore voxels at this resolution";
    return result;
  }
  const Lattice lattice(grid, axis);
  const auto& n = lattice.shape();
  std::vector<std::uint8_t> active = reachable_from_face(lattice, grid, diffusivity, a, 0);
  {
    const std::vector<std::uint8_t> from_outlet = reachable_from_face(lattice, grid, diffusivity, a, n[a] - 1);
    std::size_t count = 0;
    for (std::size_t k = 0; k < size; ++k) {
      active[k] = static_cast<std::uint8_t>(active[k] & from_outlet[k]);
      count += active[k];
    }
    result.conducting_fraction = static_cast<double>(count) / static_cast<double>(size);
    if (count == 0) {
      result.reason = "no pore path connects " + faces + " (the pore phase does not percolate along " + kAxisName[a] +
                      " at this resolution)";
      return result;
    }
  }

  // Conductances per unit diffusivity: face area over centre distance, per axis.
  const Eigen::Vector3d& h = grid.spacing;
  const std::array<double, 3> conductance{h.y() * h.z() / h.x(), h.x() * h.z() / h.y(), h.x() * h.y() / h.z()};
  const double boundary = 2.0 * conductance[a];  // face voxel to its face: half a voxel
  const auto slices = static_cast<std::size_t>(n[2]);
  // Threads only for grids worth a fork/join per sweep (the sums are per slice either way).
  const bool parallel = size >= kParallelVoxels;
  std::vector<double> slice_sums(slices);
  // Calls visit(k, at) for every active voxel, slice by slice in parallel; each slice writes its
  // own partial sum (visit's return value), summed afterwards in slice order: deterministic.
  const auto reduce = [&](const auto& visit) {
#pragma omp parallel for schedule(static) if (parallel)
    for (int i2 = 0; i2 < n[2]; ++i2) {
      double sum = 0.0;
      for (int i1 = 0; i1 < n[1]; ++i1)
        for (int i0 = 0; i0 < n[0]; ++i0) {
          const std::size_t k = grid.index(i0, i1, i2);
          if (active[k] != 0) sum += visit(k, std::array<int, 3>{i0, i1, i2});
        }
      slice_sums[static_cast<std::size_t>(i2)] = sum;
    }
    double total = 0.0;
    for (const double s : slice_sums) total += s;
    return total;
  };
  const auto boundary_conductance = [&](std::size_t k, const std::array<int, 3>& at) {
    return (at[a] == 0 || at[a] == n[a] - 1 ? boundary * diffusivity[k] : 0.0) *
           (n[a] == 1 ? 2.0 : 1.0);  // a one-voxel-thick grid touches both faces
  };
  std::vector<double> diagonal(size, 0.0);
  std::vector<double> x(size, 0.0);
  std::vector<double> r(size, 0.0);
  std::vector<double> p(size, 0.0);
  std::vector<double> q(size, 0.0);
  // The stopping test is on the preconditioned residual: r·D⁻¹r ≤ tol² b·D⁻¹b.
  const double b_norm2 = reduce([&](std::size_t k, const std::array<int, 3>& at) {
    double sum = boundary_conductance(k, at);
    for (std::size_t b = 0; b < 3; ++b)
      for (const int step : {-1, 1}) {
        const long m = lattice.neighbour(at, b, step);
        if (m >= 0 && active[static_cast<std::size_t>(m)] != 0)
          sum += conductance[b] * harmonic_mean(diffusivity[k], diffusivity[static_cast<std::size_t>(m)]);
      }
    diagonal[k] = sum;
    x[k] = 1.0 - (at[a] + 0.5) / n[a];                                   // the linear profile
    const double inflow = at[a] == 0 ? boundary * diffusivity[k] : 0.0;  // b: c = 1 on the inlet face
    r[k] = inflow;
    return inflow * inflow / sum;
  });
  // y = A v over the active voxels. The neighbour lines along y and z come from the lattice once
  // per line; along x the index steps by one (wrapping where periodic). A field of one positive
  // diffusivity (the pore phase) skips the harmonic means: every active pair conducts fully.
  bool uniform = true;
  double first_open = 0.0;
  for (const double d : diffusivity)
    if (d > 0.0) {
      if (first_open == 0.0) first_open = d;
      uniform = uniform && d == first_open;
    }
  const bool wrap_x = grid.periodic[0] && a != 0 && n[0] >= 2;
  const auto apply = [&](const std::vector<double>& v, std::vector<double>& y) {
#pragma omp parallel for schedule(static) if (parallel)
    for (int i2 = 0; i2 < n[2]; ++i2)
      for (int i1 = 0; i1 < n[1]; ++i1) {
        const std::array<int, 3> line{0, i1, i2};
        const long base = static_cast<long>(grid.index(0, i1, i2));
        const std::array<long, 4> across{lattice.neighbour(line, 1, -1), lattice.neighbour(line, 1, 1),
                                         lattice.neighbour(line, 2, -1), lattice.neighbour(line, 2, 1)};
        for (int i0 = 0; i0 < n[0]; ++i0) {
          const long k = base + i0;
          const auto kk = static_cast<std::size_t>(k);
          if (active[kk] == 0) continue;
          double sum = diagonal[kk] * v[kk];
          const auto couple = [&](long m, double c) {
            if (m < 0) return;
            const auto mm = static_cast<std::size_t>(m);
            if (active[mm] == 0) return;
            sum -= (uniform ? c * first_open : c * harmonic_mean(diffusivity[kk], diffusivity[mm])) * v[mm];
          };
          couple(i0 > 0 ? k - 1 : (wrap_x ? k + n[0] - 1 : -1), conductance[0]);
          couple(i0 < n[0] - 1 ? k + 1 : (wrap_x ? k - n[0] + 1 : -1), conductance[0]);
          couple(across[0] >= 0 ? across[0] + i0 : -1, conductance[1]);
          couple(across[1] >= 0 ? across[1] + i0 : -1, conductance[1]);
          couple(across[2] >= 0 ? across[2] + i0 : -1, conductance[2]);
          couple(across[3] >= 0 ? across[3] + i0 : -1, conductance[2]);
          y[kk] = sum;
        }
      }
  };
  // r = b − A x (r holds b).
  apply(x, q);
  double rz = reduce([&](std::size_t k, const std::array<int, 3>&) {
    r[k] -= q[k];
    p[k] = r[k] / diagonal[k];
    return r[k] * p[k];
  });
  const double tolerance2 = options.relative_tolerance * options.relative_tolerance * b_norm2;
  int iteration = 0;
  while (rz > tolerance2 && iteration < options.max_iterations) {
    apply(p, q);
    const double pq = reduce([&](std::size_t k, const std::array<int, 3>&) { return p[k] * q[k]; });
    if (!(pq > 0.0)) break;
    const double alpha = rz / pq;
    // x += α p, r −= α q, and r·z (z = D⁻¹ r) in one sweep.
    const double rz_next = reduce([&](std::size_t k, const std::array<int, 3>&) {
      x[k] += alpha * p[k];
      r[k] -= alpha * q[k];
      return r[k] * r[k] / diagonal[k];
    });
    const double beta = rz_next / rz;
    rz = rz_next;
    reduce([&](std::size_t k, const std::array<int, 3>&) {
      p[k] = r[k] / diagonal[k] + beta * p[k];
      return 0.0;
    });
    ++iteration;
  }
  result.iterations = iteration;
  result.converged = rz <= tolerance2;

  // Fluxes through the inlet and the outlet face (Δc = 1).
  const double flux_in = reduce([&](std::size_t k, const std::array<int, 3>& at) {
    return at[a] == 0 ? boundary * diffusivity[k] * (1.0 - x[k]) : 0.0;
  });
  const double flux_out = reduce([&](std::size_t k, const std::array<int, 3>& at) {
    return at[a] == n[a] - 1 ? boundary * diffusivity[k] * x[k] : 0.0;
  });
  const double flux = 0.5 * (flux_in + flux_out);
  const Eigen::Vector3d lengths(n[0] * h.x(), n[1] * h.y(), n[2] * h.z());
  const double area = lengths.prod() / lengths[axis];
  result.flux_mismatch = flux_in > 0.0 ? std::abs(flux_in - flux_out) / flux_in : 0.0;
  result.effective_diffusivity = flux * lengths[axis] / (area * bulk);
  result.percolating = true;
  result.tortuosity = result.porosity / result.effective_diffusivity;
  if (!result.converged)
    result.reason = "conjugate gradients stopped after " + std::to_string(iteration) +
                    " iterations above the tolerance (flux mismatch " + std::to_string(result.flux_mismatch) + ")";
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

DiffusionResult tortuosity_factor(const VoxelGrid& grid, int axis, const DiffusionOptions& options) {
  std::vector<double> diffusivity(grid.size());
  for (std::size_t k = 0; k < diffusivity.size(); ++k) diffusivity[k] = grid.solid[k] != 0 ? 0.0 : 1.0;
  return solve_diffusion(grid, diffusivity, axis, 1.0, options);
}

std::optional<double> extrapolated_tortuosity(double at_spacing, double at_coarse, double factor) noexcept {
  if (!(std::isfinite(at_spacing) && std::isfinite(at_coarse) && at_spacing > 0.0 && at_coarse > 0.0 &&
        std::isfinite(factor) && factor > 1.0))
    return std::nullopt;
  return at_spacing + (at_spacing - at_coarse) / (factor - 1.0);
}

TortuosityExtrapolation extrapolate_tortuosity(double at_spacing, double at_coarse, double factor,
                                               double coarse_voxels_per_semi_axis) {
  TortuosityExtrapolation result;
  const auto estimate = extrapolated_tortuosity(at_spacing, at_coarse, factor);
  if (!estimate) {
    result.reason = "no finite tortuosity at both voxel sizes";
  } else if (!(coarse_voxels_per_semi_axis >= kMinCoarseVoxelsPerSemiAxis * (1.0 - 1e-9))) {
    result.reason = "not extrapolated: the coarse grid has " + format_number(coarse_voxels_per_semi_axis) +
                    " voxels per smallest semi-axis, under " + format_number(kMinCoarseVoxelsPerSemiAxis) +
                    " (a finer voxel size, e.g. the default 5 voxels per semi-axis, gives one)";
  } else if (*estimate < 1.0) {
    result.reason = "not extrapolated: the line through the two values reaches " + format_number(*estimate) +
                    " < 1 at zero voxel size (tau >= 1 always): outside the first-order range";
  } else {
    result.tortuosity = estimate;
  }
  return result;
}

double fit_bruggeman_exponent(const std::vector<double>& porosity, const std::vector<double>& tortuosity) {
  double sxy = 0.0;
  double sxx = 0.0;
  for (std::size_t k = 0; k < porosity.size() && k < tortuosity.size(); ++k) {
    const double e = porosity[k];
    const double t = tortuosity[k];
    if (!(e > 0.0 && e < 1.0 && std::isfinite(t) && t > 0.0)) continue;
    sxy += std::log(e) * std::log(t);
    sxx += std::log(e) * std::log(e);
  }
  return sxx > 0.0 ? 1.0 - sxy / sxx : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace ellc::microstructure
