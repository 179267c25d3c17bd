#include "ellc/hertz/elliptic_hertz.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "ellc/hertz/elliptic_integrals.hpp"

namespace ellc {

namespace {

constexpr double kPi = std::numbers::pi;

// Complete integrals of parameter m = e² in the forms the exact solution needs, with the
// complementary parameter q = 1 − m = k² as input (precise for very elongated contacts):
//   K = R_F(0, q, 1),  K − E = (m/3) R_D(0, q, 1),  E = K − (m/3) R_D.
struct CompleteIntegrals {
  double rf;  // = K(m)
  double rd;  // R_D(0, q, 1)
};

CompleteIntegrals complete_integrals(double q) noexcept {
  return {elliptic::carlson_rf(0.0, q, 1.0), elliptic::carlson_rd(0.0, q, 1.0)};
}

// B/A as a function of q = (b_c/a_c)²: (E/k² − K)/(K − E) = (3 R_F − R_D) / (q R_D).
// Written without the cancelling differences, so it is exact as q → 1 (where it equals 1).
double curvature_ratio_of(double q) noexcept {
  const auto [rf, rd] = complete_integrals(q);
  return (3.0 * rf - rd) / (q * rd);
}

// Solves curvature_ratio_of(q) = ratio (≥ 1) for q in (0, 1]; the ratio falls monotonically in q.
// Regula falsi (Illinois) on t = ln q, bracketed, started from Hale's q ≈ (A/B)^{4/3}.
double solve_axis_ratio_sq(double ratio) noexcept {
  if (ratio <= 1.0) return 1.0;
  const double target = std::log(ratio);
  auto residual = [target](double t) { return std::log(curvature_ratio_of(std::exp(t))) - target; };

  double t_high = 0.0;  // q = 1: residual = −target < 0
  double r_high = -target;
  double t_low = std::min(-1e-12, -(4.0 / 3.0) * target);  // Hale's guess, usually close
  double r_low = residual(t_low);
  while (r_low < 0.0) {  // too round: move towards elongated until bracketed
    t_high = t_low;
    r_high = r_low;
    t_low = 2.0 * t_low - 1.0;
    r_low = residual(t_low);
  }
  int stale_side = 0;
  for (int iteration = 0; iteration < 200; ++iteration) {
    const double t = (t_low * r_high - t_high * r_low) / (r_high - r_low);
    const double r = residual(t);
    if (r == 0.0 || std::abs(t_high - t_low) < 1e-15 * (1.0 + std::abs(t))) return std::exp(t);
    if (r > 0.0) {
      t_low = t;
      r_low = r;
      if (stale_side == -1) r_high *= 0.5;
      stale_side = -1;
    } else {
      t_high = t;
      r_high = r;
      if (stale_side == 1) r_low *= 0.5;
      stale_side = 1;
    }
    if (std::abs(r) < 1e-16) return std::exp(t);
  }
  return std::exp(0.5 * (t_low + t_high));
}

// x^y for x ≥ 0, y > 0 (0 at x = 0): one exp and one log, a third of the cost of std::pow.
double positive_power(double x, double y) noexcept { return x > 0.0 ? std::exp(y * std::log(x)) : 0.0; }

// log(eˣ − 1) for 0 < x ≤ kSeriesLimit, given log x: log x + x/2 + log(sinh(x/2) / (x/2)), the
// last term by its Taylor series Σ 2²ⁿ B₂ₙ y²ⁿ / (2n (2n)!) in y = x/2 (B₂ₙ Bernoulli numbers).
// Through n = 7 the truncation is below 10⁻¹⁸ for y ≤ 1/4: the result is the direct
// log(expm1(x)) to rounding, without the expm1 and the log of it.
constexpr double kSeriesLimit = 0.5;
double log_expm1_small(double x, double log_x) noexcept {
  const double y2 = 0.25 * x * x;
  const double series =
      y2 * (1.0 / 6.0 +
            y2 * (-1.0 / 180.0 + y2 * (1.0 / 2835.0 + y2 * (-1.0 / 37800.0 +
                                                            y2 * (1.0 / 467775.0 + y2 * (-691.0 / 3831077250.0 +
                                                                                         y2 * (2.0 / 127702575.0)))))));
  return log_x + 0.5 * x + series;
}

HertzShape hale_shape(double equivalent_radius, double ratio, ShapeParts parts) noexcept {
  // Eq. (4) and (7) as corrected in docs/model.md §1, with B/A ≥ 1:
  //   e² = 1 − (A/B)^{4/3},  f1 = 1 − ((B/A)^0.0602 − 1)^1.456,  f2 = 1 − ((B/A)^0.0684 − 1)^1.531.
  // A DEM evaluates this per contact and step, so the transcendental calls are counted: every
  // power of B/A shares one logarithm L, expm1 keeps (B/A)^p − 1 exact near B/A = 1, and for
  // B/A up to e^{0.5/0.0684} ≈ 1500, ((B/A)^p − 1)^q = exp(q log(expm1(pL))) takes log(expm1(pL))
  // from log L and a series (5 calls instead of 8; the same numbers to rounding, tested).
  constexpr double kPower1 = 0.0602, kPower2 = 0.0684;
  const double log_ratio = std::log(ratio);
  HertzShape shape;
  shape.equivalent_radius = equivalent_radius;
  // e² = 1 − e^{−x}: where e^{−x} ≤ ½, 1 − exp(−x) is within about an ulp, and exp costs a
  // fraction of expm1 (measured: expm1 alone took 4 % of a DEM step); below, expm1 keeps the
  // small e² to full relative precision.
  const double eccentricity_exponent = (4.0 / 3.0) * log_ratio;
  if (parts == ShapeParts::all) {
    shape.eccentricity_sq = eccentricity_exponent > std::numbers::ln2 ? 1.0 - std::exp(-eccentricity_exponent)
                                                                      : -std::expm1(-eccentricity_exponent);
  } else {
    shape.eccentricity_sq = std::numeric_limits<double>::quiet_NaN();  // not asked for: visible if read
  }
  if (log_ratio > 0.0 && kPower2 * log_ratio <= kSeriesLimit) {
    const double log_log_ratio = std::log(log_ratio);
    static const double log_power1 = std::log(kPower1);
    static const double log_power2 = std::log(kPower2);
    shape.f1 = 1.0 - std::exp(1.456 * log_expm1_small(kPower1 * log_ratio, log_power1 + log_log_ratio));
    shape.f2 = 1.0 - std::exp(1.531 * log_expm1_small(kPower2 * log_ratio, log_power2 + log_log_ratio));
  } else {
    shape.f1 = 1.0 - positive_power(std::expm1(kPower1 * log_ratio), 1.456);
    shape.f2 = 1.0 - positive_power(std::expm1(kPower2 * log_ratio), 1.531);
  }
  return shape;
}

HertzShape exact_shape(double equivalent_radius, double ratio) noexcept {
  // With q = k², ρ = B/A: from Johnson's relations and eq. (9), (10) (derivation in docs/model.md)
  //   f2^{3/2} = 2 K^{3/2} / (π sqrt(2 sqrt(ρ) R_D/3)),   f1² = f2 · 2 k sqrt(ρ) (R_D/3) / K.
  const double q = solve_axis_ratio_sq(ratio);
  const auto [rf, rd] = complete_integrals(q);
  const double sqrt_ratio = std::sqrt(ratio);
  HertzShape shape;
  shape.equivalent_radius = equivalent_radius;
  shape.eccentricity_sq = 1.0 - q;
  shape.f2 = std::cbrt(std::pow(2.0 * std::pow(rf, 1.5) / (kPi * std::sqrt(2.0 * sqrt_ratio * rd / 3.0)), 2.0));
  shape.f1 = std::sqrt(shape.f2 * 2.0 * std::sqrt(q) * sqrt_ratio * (rd / 3.0) / rf);
  return shape;
}

}  // namespace

RelativeCurvature relative_curvature(PrincipalCurvatures body_i, PrincipalCurvatures body_j, double alpha) noexcept {
  const double cos_two_alpha = std::cos(2.0 * alpha);
  const double sum = 0.5 * (body_i.kappa_1 + body_i.kappa_2 + body_j.kappa_1 + body_j.kappa_2);
  const double split_i = body_i.kappa_1 - body_i.kappa_2;
  const double split_j = body_j.kappa_1 - body_j.kappa_2;
  // The radicand is |Δ_I e^{2iα} + Δ_J|² ≥ 0 mathematically; clamp rounding below zero.
  const double radicand = split_i * split_i + split_j * split_j + 2.0 * split_i * split_j * cos_two_alpha;
  const double difference = 0.5 * std::sqrt(std::max(radicand, 0.0));
  return {0.5 * (sum - difference), 0.5 * (sum + difference)};
}

RelativeCurvature relative_curvature_from_tensor(double sum_11, double sum_12, double sum_22) noexcept {
  const double half_split = 0.5 * (sum_11 - sum_22);
  const double sum = 0.5 * (sum_11 + sum_22);                                      // A + B = ½ tr W
  const double difference = std::sqrt(half_split * half_split + sum_12 * sum_12);  // B − A
  return {0.5 * (sum - difference), 0.5 * (sum + difference)};
}

HertzShape hertz_shape(RelativeCurvature curvature, HertzMode mode, ShapeParts parts) noexcept {
  const double equivalent_radius = 0.5 / std::sqrt(curvature.a_sum * curvature.b_sum);
  const double ratio = std::max(curvature.b_sum / curvature.a_sum, 1.0);
  return mode == HertzMode::exact ? exact_shape(equivalent_radius, ratio) : hale_shape(equivalent_radius, ratio, parts);
}

HertzContact hertz_contact(const HertzShape& shape, double effective_modulus, double overlap) noexcept {
  HertzContact contact;
  if (!(overlap > 0.0)) return contact;
  const double radius_sq = shape.contact_radius_sq_per_overlap() * overlap;  // eq. (9)
  const double radius = std::sqrt(radius_sq);
  const double axis_stretch = std::sqrt(std::sqrt(1.0 - shape.eccentricity_sq));  // (1 − e²)^{1/4}
  contact.equivalent_contact_radius = radius;
  contact.semi_axis_major = radius / axis_stretch;  // eq. (8)
  contact.semi_axis_minor = radius * axis_stretch;
  contact.peak_pressure =
      2.0 * effective_modulus * radius / (kPi * shape.equivalent_radius * shape.f1 * shape.f1 * shape.f1);  // eq. (2)
  contact.force = (4.0 / 3.0) * effective_modulus * std::sqrt(shape.equivalent_radius) * overlap * std::sqrt(overlap) /
                  (shape.f2 * std::sqrt(shape.f2));  // eq. (10)
  return contact;
}

double hertz_pressure(double semi_axis_major, double semi_axis_minor, double peak_pressure, double x,
                      double y) noexcept {
  const double u = x / semi_axis_major;
  const double v = y / semi_axis_minor;
  const double inside = 1.0 - u * u - v * v;
  return inside > 0.0 ? peak_pressure * std::sqrt(inside) : 0.0;  // eq. (1)
}

}  // namespace ellc
