#include "ellc/hertz/elliptic_integrals.hpp"

#include <algorithm>
#include <cmath>

// Duplication algorithm of Carlson (1995), "Numerical computation of real or complex elliptic
// integrals", Numer. Algorithms 10, with the fifth-order series at the end. The loop stops when
// the spread of the arguments makes the truncated series exact to double precision.

namespace ellc::elliptic {

namespace {
// Loop until max|Δ| < tolerance: the series error is O(Δ⁶) ≈ 1e-17 relative.
constexpr double kTolerance = 1.0e-3;
constexpr int kMaxIterations = 64;
}  // namespace

double carlson_rf(double x, double y, double z) noexcept {
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    const double mean = (x + y + z) / 3.0;
    const double dx = 1.0 - x / mean;
    const double dy = 1.0 - y / mean;
    const double dz = 1.0 - z / mean;
    if (std::max({std::abs(dx), std::abs(dy), std::abs(dz)}) < kTolerance) {
      const double e2 = dx * dy - dz * dz;
      const double e3 = dx * dy * dz;
      return (1.0 - e2 / 10.0 + e3 / 14.0 + e2 * e2 / 24.0 - 3.0 * e2 * e3 / 44.0) / std::sqrt(mean);
    }
    const double sx = std::sqrt(x);
    const double sy = std::sqrt(y);
    const double sz = std::sqrt(z);
    const double lambda = sx * sy + sx * sz + sy * sz;
    x = 0.25 * (x + lambda);
    y = 0.25 * (y + lambda);
    z = 0.25 * (z + lambda);
  }
  return std::nan("");
}

double carlson_rd(double x, double y, double z) noexcept {
  double sum = 0.0;
  double factor = 1.0;
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    const double mean = (x + y + 3.0 * z) / 5.0;
    const double dx = 1.0 - x / mean;
    const double dy = 1.0 - y / mean;
    const double dz = 1.0 - z / mean;
    if (std::max({std::abs(dx), std::abs(dy), std::abs(dz)}) < kTolerance) {
      const double ea = dx * dy;
      const double eb = dz * dz;
      const double ec = ea - eb;
      const double ed = ea - 6.0 * eb;
      const double ef = ed + ec + ec;
      const double s1 = ed * (-3.0 / 14.0 + 9.0 / 88.0 * ed - 4.5 / 26.0 * dz * ef);
      const double s2 = dz * (ef / 6.0 + dz * (-9.0 / 22.0 * ec + 3.0 / 26.0 * dz * ea));
      return 3.0 * sum + factor * (1.0 + s1 + s2) / (mean * std::sqrt(mean));
    }
    const double sx = std::sqrt(x);
    const double sy = std::sqrt(y);
    const double sz = std::sqrt(z);
    const double lambda = sx * sy + sx * sz + sy * sz;
    sum += factor / (sz * (z + lambda));
    factor *= 0.25;
    x = 0.25 * (x + lambda);
    y = 0.25 * (y + lambda);
    z = 0.25 * (z + lambda);
  }
  return std::nan("");
}

}  // namespace ellc::elliptic
