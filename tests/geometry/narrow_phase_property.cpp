#include "narrow_phase_property.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "ellc/geometry/narrow_phase.hpp"
#include "support/geometry_support.hpp"

namespace ellc::test {
namespace {

enum class BodyShape : std::uint8_t { ordinary, flat, slender, triaxial };

double log_uniform(Rng& rng, double low, double high) { return std::exp(uniform(rng, std::log(low), std::log(high))); }

// Semi-axes with mean radius r̂ = (abc)^{1/3}; flat: a ≥ b ≥ a/2, c = a/k; slender: a = k c,
// c ≤ b ≤ 2c (half of each exactly a = b, b = c); triaxial: a, b log-uniform in [c, a], c = a/k. Largest/smallest = k
// (ordinary: ≤ 10).
Eigen::Vector3d body_semi_axes(Rng& rng, BodyShape shape, double aspect, double mean_radius) {
  Eigen::Vector3d ratios = Eigen::Vector3d::Ones();  // every case sets it; the compiler cannot see that
  switch (shape) {
    case BodyShape::ordinary: return random_semi_axes(rng, mean_radius);
    case BodyShape::flat:  // half of them discs (a = b): a flat valley of g along the whole rim
      ratios = {1.0, uniform(rng, 0.0, 1.0) < 0.5 ? 1.0 : uniform(rng, 0.5, 1.0), 1.0 / aspect};
      break;
    case BodyShape::slender:  // half of them round needles (b = c)
      ratios = {1.0, uniform(rng, 0.0, 1.0) < 0.5 ? 1.0 / aspect : std::min(1.0, uniform(rng, 1.0, 2.0) / aspect),
                1.0 / aspect};
      break;
    case BodyShape::triaxial: ratios = {1.0, log_uniform(rng, 1.0 / aspect, 1.0), 1.0 / aspect}; break;
  }
  return ratios * (mean_radius / std::cbrt(ratios.prod()));
}

// The thinnest body axis along `direction`, tilted by at most 2°, twisted at random about it.
Eigen::Quaterniond face_towards(Rng& rng, const Eigen::Vector3d& semi_axes, const Eigen::Vector3d& direction) {
  Eigen::Index thinnest = 0;
  semi_axes.minCoeff(&thinnest);
  const Eigen::Quaterniond twist(
      Eigen::AngleAxisd(uniform(rng, 0.0, 2.0 * std::numbers::pi), Eigen::Vector3d::Unit(static_cast<int>(thinnest))));
  const Eigen::Quaterniond tilt(Eigen::AngleAxisd(uniform(rng, 0.0, 2.0) * std::numbers::pi / 180.0, random_unit(rng)));
  return tilt * align_axis(static_cast<int>(thinnest), direction) * twist;
}

struct Sample {
  Ellipsoid i;
  Ellipsoid j;
  PairShape shape;
  int aspect_bin;
  DepthBin depth;
  double overlap;  // constructed
};

Sample make_sample(Rng& rng, long index) {
  const auto shape = static_cast<PairShape>(index % 4);
  BodyShape shape_i = BodyShape::ordinary;
  BodyShape shape_j = BodyShape::ordinary;
  switch (shape) {
    case PairShape::ordinary: break;
    case PairShape::flat: shape_i = shape_j = BodyShape::flat; break;
    case PairShape::slender: shape_i = shape_j = BodyShape::slender; break;
    case PairShape::mixed:
      shape_i = static_cast<BodyShape>(1 + static_cast<int>(uniform(rng, 0.0, 3.0)) % 3);
      shape_j = static_cast<BodyShape>(1 + static_cast<int>(uniform(rng, 0.0, 3.0)) % 3);
      break;
  }
  const Eigen::Vector3d axes_i =
      body_semi_axes(rng, shape_i, log_uniform(rng, 1.0, 100.0), log_uniform(rng, 0.1, 10.0));
  const Eigen::Vector3d axes_j =
      body_semi_axes(rng, shape_j, log_uniform(rng, 1.0, 100.0), log_uniform(rng, 0.1, 10.0));
  const double aspect = std::max(axes_i.maxCoeff() / axes_i.minCoeff(), axes_j.maxCoeff() / axes_j.minCoeff());
  const int aspect_bin = static_cast<int>(std::upper_bound(kAspectBinUpper.begin(), kAspectBinUpper.end(), aspect) -
                                          kAspectBinUpper.begin());
  const double smallest = std::min(axes_i.minCoeff(), axes_j.minCoeff());

  // Depth: 10 % separated, 10 % grazing, 30 % 0–1 % (log-uniform from 1e-6), 30 % 1–10 %,
  // 10 % 10–30 %, 10 % 30–100 % of the smallest semi-axis.
  const long slot = (index / 4) % 10;
  DepthBin depth = DepthBin::moderate;
  double overlap = 0.0;
  if (slot == 0) {
    depth = DepthBin::separated;
    overlap = -uniform(rng, 0.0, 0.2);
  } else if (slot == 1) {
    depth = DepthBin::grazing;
    overlap = uniform(rng, -1e-7, 1e-7);
  } else if (slot <= 4) {
    depth = DepthBin::shallow;
    overlap = log_uniform(rng, 1e-6, 1e-2);
  } else if (slot <= 7) {
    depth = DepthBin::moderate;
    overlap = uniform(rng, 0.01, 0.1);
  } else if (slot == 8) {
    depth = DepthBin::deep;
    overlap = uniform(rng, 0.1, 0.3);
  } else {
    depth = DepthBin::very_deep;
    overlap = uniform(rng, 0.3, 1.0);
  }
  overlap *= smallest;

  const Eigen::Vector3d n = random_unit(rng);
  Eigen::Quaterniond orientation_i = random_orientation(rng);
  Eigen::Quaterniond orientation_j = random_orientation(rng);
  if (shape == PairShape::flat && uniform(rng, 0.0, 1.0) < 0.25) {  // faces nearly parallel
    orientation_i = face_towards(rng, axes_i, n);
    orientation_j = face_towards(rng, axes_j, -n);
  }
  const Eigen::Vector3d centre(uniform(rng, -100, 100), uniform(rng, -100, 100), uniform(rng, -100, 100));
  const Ellipsoid i(axes_i, {centre, orientation_i});
  return {i, place_partner(i, axes_j, orientation_j, n, overlap), shape, aspect_bin, depth, overlap};
}

bool finite(const NarrowPhaseResult& result) {
  const ContactGeometry& g = result.geometry;
  return g.point.allFinite() && g.normal.allFinite() && std::isfinite(g.overlap) && g.surface_point_i.allFinite() &&
         g.surface_point_j.allFinite() && std::isfinite(g.alpha) && std::isfinite(g.curvature_i.kappa_1) &&
         std::isfinite(g.curvature_i.kappa_2) && std::isfinite(g.curvature_j.kappa_1) &&
         std::isfinite(g.curvature_j.kappa_2) && g.curvature_i.direction_1.allFinite() &&
         g.curvature_i.direction_2.allFinite() && g.curvature_j.direction_1.allFinite() &&
         g.curvature_j.direction_2.allFinite() && std::isfinite(g.relative.a_sum) && std::isfinite(g.relative.b_sum) &&
         std::isfinite(result.warm_start.normal[0]) && std::isfinite(result.warm_start.normal[1]) &&
         std::isfinite(result.warm_start.normal[2]);
}

// A genuine common normal (a stationary point of g with the surfaces' normals anti-parallel
// along the joining line, convex on both sides). Not necessarily the constructed one: when δ
// exceeds the local radii of curvature (the rim of a thin body) g has several minima.
bool verified_contact(const Ellipsoid& i, const Ellipsoid& j, const NarrowPhaseResult& result) {
  const ContactGeometry& g = result.geometry;
  const double reach = i.bounding_radius() + j.bounding_radius();
  const Eigen::Vector3d joining = g.surface_point_i - g.surface_point_j;
  return g.overlap > 0.0 && std::abs(g.normal.norm() - 1.0) < 1e-12 &&
         (i.normal_at(g.surface_point_i) - g.normal).norm() < 1e-8 &&
         (j.normal_at(g.surface_point_j) + g.normal).norm() < 1e-8 &&
         (joining - joining.dot(g.normal) * g.normal).norm() < 1e-9 * reach &&
         std::abs(joining.dot(g.normal) - g.overlap) < 1e-12 * reach && g.curvature_i.kappa_2 > 0.0 &&
         g.curvature_i.kappa_1 >= g.curvature_i.kappa_2 && g.curvature_j.kappa_2 > 0.0 &&
         g.curvature_j.kappa_1 >= g.curvature_j.kappa_2 && g.relative.a_sum > 0.0 &&
         g.relative.a_sum <= g.relative.b_sum;
}

// A genuine separating axis.
bool verified_separation(const Ellipsoid& i, const Ellipsoid& j, const NarrowPhaseResult& result) {
  const Eigen::Vector3d& n = result.geometry.normal;
  const double along = i.support_radius(n) + j.support_radius(-n) - n.dot(j.center() - i.center());
  return result.geometry.overlap <= 0.0 && along <= 1e-12 * (i.bounding_radius() + j.bounding_radius());
}

void add(PropertyCell& sum, const PropertyCell& cell) {
  sum.pairs += cell.pairs;
  sum.contact += cell.contact;
  sum.separated += cell.separated;
  sum.failed += cell.failed;
  sum.non_finite += cell.non_finite;
  sum.unverified += cell.unverified;
  sum.swap_mismatch += cell.swap_mismatch;
  sum.newton_steps += cell.newton_steps;
  sum.other_minimum += cell.other_minimum;
}

}  // namespace

PropertyCell PropertyReport::total() const {
  PropertyCell sum;
  for (const auto& by_aspect : cells)
    for (const auto& by_depth : by_aspect)
      for (const auto& cell : by_depth) add(sum, cell);
  return sum;
}

PropertyCell PropertyReport::depth_total(DepthBin depth) const {
  PropertyCell sum;
  for (const auto& by_aspect : cells)
    for (const auto& by_depth : by_aspect) add(sum, by_depth[static_cast<int>(depth)]);
  return sum;
}

long PropertyReport::required_failures() const {
  long count = 0;
  for (DepthBin depth : {DepthBin::separated, DepthBin::grazing, DepthBin::shallow, DepthBin::moderate}) {
    const PropertyCell sum = depth_total(depth);
    count += sum.failed + sum.non_finite + sum.unverified + sum.swap_mismatch;
  }
  return count;
}

std::string PropertyReport::text() const {
  std::string out;
  char line[512];
  const PropertyCell all = total();
  std::snprintf(
      line, sizeof line,
      "narrow_phase_property: %ld pairs in %.1f s: %ld contact, %ld separated, %ld failed, %ld non-finite, "
      "%ld unverified, %ld swap mismatches; mean Newton steps %.2f; %ld at another common normal\n",
      pairs, seconds, all.contact, all.separated, all.failed, all.non_finite, all.unverified, all.swap_mismatch,
      all.pairs > 0 ? static_cast<double>(all.newton_steps) / static_cast<double>(all.pairs) : 0.0, all.other_minimum);
  out += line;
  std::snprintf(line, sizeof line,
                "swap symmetry: max |delta(I,J) - delta(J,I)| = %.2e of (a_max^I + a_max^J), max |n(I,J) + n(J,I)| = "
                "%.2e\n",
                max_swap_overlap_difference, max_swap_normal_difference);
  out += line;
  out +=
      "failed (non-finite / unverified / swap mismatch when not 0) of pairs, by shape, largest aspect ratio and "
      "overlap depth / smallest semi-axis:\n";
  std::snprintf(line, sizeof line, "%-9s %-7s", "shape", "aspect");
  out += line;
  for (const char* name : kDepthBinNames) {
    std::snprintf(line, sizeof line, " | %-20s", name);
    out += line;
  }
  out += "\n";
  for (std::size_t shape = 0; shape < cells.size(); ++shape) {
    for (std::size_t aspect = 0; aspect < cells[shape].size(); ++aspect) {
      std::snprintf(line, sizeof line, "%-9s %-7s", kPairShapeNames[shape], kAspectBinNames[aspect]);
      out += line;
      for (const PropertyCell& cell : cells[shape][aspect]) {
        std::string entry = std::to_string(cell.failed) + "/" + std::to_string(cell.pairs);
        if (cell.non_finite + cell.unverified + cell.swap_mismatch > 0)
          entry += " (" + std::to_string(cell.non_finite) + "/" + std::to_string(cell.unverified) + "/" +
                   std::to_string(cell.swap_mismatch) + ")";
        std::snprintf(line, sizeof line, " | %-20s", entry.c_str());
        out += line;
      }
      out += "\n";
    }
  }
  out += "by depth (all shapes):";
  for (std::size_t depth = 0; depth < kDepthBinNames.size(); ++depth) {
    const PropertyCell sum = depth_total(static_cast<DepthBin>(depth));
    std::snprintf(line, sizeof line,
                  "\n  %-21s %ld failed of %ld (%.4f %%), %ld non-finite, %ld unverified, %ld swap, %ld other minimum",
                  kDepthBinNames[depth], sum.failed, sum.pairs,
                  sum.pairs > 0 ? 100.0 * static_cast<double>(sum.failed) / static_cast<double>(sum.pairs) : 0.0,
                  sum.non_finite, sum.unverified, sum.swap_mismatch, sum.other_minimum);
    out += line;
  }
  std::snprintf(line, sizeof line, "\nrequired (separated, grazing, 0..10 %%): %ld failures\n", required_failures());
  out += line;
  return out;
}

PropertyReport run_narrow_phase_property(long pairs, std::uint64_t seed) {
  PropertyReport report;
  report.pairs = pairs;
  Rng rng(seed);
  const auto start = std::chrono::steady_clock::now();
  for (long index = 0; index < pairs; ++index) {
    const Sample s = make_sample(rng, index);
    PropertyCell& cell =
        report.cells[static_cast<int>(s.shape)][static_cast<std::size_t>(s.aspect_bin)][static_cast<int>(s.depth)];
    ++cell.pairs;
    const NarrowPhaseResult forward = ellipsoid_contact(s.i, s.j);
    const NarrowPhaseResult swapped = ellipsoid_contact(s.j, s.i);
    cell.newton_steps += forward.iterations;
    if (!finite(forward) || !finite(swapped)) {
      ++cell.non_finite;
      continue;
    }
    if (forward.status == NarrowPhaseStatus::failed || swapped.status == NarrowPhaseStatus::failed) {
      ++cell.failed;
      continue;
    }
    const bool verified = forward.status == NarrowPhaseStatus::contact
                              ? verified_contact(s.i, s.j, forward) && verified_contact(s.j, s.i, swapped)
                              : verified_separation(s.i, s.j, forward) && verified_separation(s.j, s.i, swapped);
    if (forward.status == NarrowPhaseStatus::contact)
      ++cell.contact;
    else
      ++cell.separated;
    const double reach = s.i.bounding_radius() + s.j.bounding_radius();
    if (forward.status != swapped.status) {
      // Only at touching may rounding put one order on either side of δ = 0.
      const NarrowPhaseResult& in_contact = forward.status == NarrowPhaseStatus::contact ? forward : swapped;
      if (in_contact.geometry.overlap > 1e-12 * reach) ++cell.swap_mismatch;
      continue;
    }
    if (!verified) ++cell.unverified;
    if (forward.status == NarrowPhaseStatus::contact) {
      if (std::abs(forward.geometry.overlap - s.overlap) > 1e-9 * reach) ++cell.other_minimum;
      const double overlap_difference = std::abs(forward.geometry.overlap - swapped.geometry.overlap) / reach;
      const double normal_difference = (forward.geometry.normal + swapped.geometry.normal).norm();
      report.max_swap_overlap_difference = std::max(report.max_swap_overlap_difference, overlap_difference);
      report.max_swap_normal_difference = std::max(report.max_swap_normal_difference, normal_difference);
      if (overlap_difference > 1e-9 || normal_difference > 1e-6) ++cell.swap_mismatch;
    }
  }
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

}  // namespace ellc::test
