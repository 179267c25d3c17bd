#include "ellc/geometry/narrow_phase.hpp"

#include <algorithm>
#include <cmath>

#include "ellc/assert.hpp"
#include "ellc/geometry/contact_function.hpp"
#include "ellc/geometry/tangent_frame.hpp"

namespace ellc {

namespace {

constexpr int kMaxNewtonSteps = 40;
constexpr double kGradientTolerance = 1e-14;  // |tangential gradient| / (ρ_I + ρ_J)
constexpr double kMaxStep = 0.5;              // radians per Newton step
constexpr double kFullStep = 1e-7;            // below this the Newton step is taken without a line search

// (EIGEN_ALWAYS_INLINE: these small kernels must be inlined into the Newton loop.)
// Both bodies are evaluated together: in every Eigen::Array2d below lane 0 belongs to I and
// lane 1 to J, so each product and each sqrt/division serves both bodies (one SSE2 instruction).
using Lanes = Eigen::Array2d;

// The overlap along a unit n and its gradient p_I(n) − p_J(n).
struct AlongNormal {
  Eigen::Vector3d normal;
  Lanes arm_x, arm_y, arm_z;  // a_k = S_k n / ρ_k: lane I = p_I − c_I, lane J = c_J − p_J
  Lanes reach;                // ρ_k(n)
  Lanes inverse_reach;        // 1 / ρ_k(n)
  double overlap;             // g(n)
  Eigen::Vector3d gradient;   // p_I − p_J

  [[nodiscard]] Eigen::Vector3d arm(int lane) const noexcept { return {arm_x[lane], arm_y[lane], arm_z[lane]}; }
};

// Two symmetric 3×3 matrices, entry by entry (six lane pairs): lane 0 of body I, lane 1 of J.
struct SymmetricLanes {
  Lanes s00, s01, s02, s11, s12, s22;

  SymmetricLanes(const Eigen::Matrix3d& of_i, const Eigen::Matrix3d& of_j) noexcept
      : s00(of_i(0, 0), of_j(0, 0)),
        s01(of_i(0, 1), of_j(0, 1)),
        s02(of_i(0, 2), of_j(0, 2)),
        s11(of_i(1, 1), of_j(1, 1)),
        s12(of_i(1, 2), of_j(1, 2)),
        s22(of_i(2, 2), of_j(2, 2)) {}

  // A_k v for both matrices, as three lane pairs.
  EIGEN_ALWAYS_INLINE void image(const Eigen::Vector3d& v, Lanes& x, Lanes& y, Lanes& z) const noexcept {
    x = s00 * v.x() + s01 * v.y() + s02 * v.z();
    y = s01 * v.x() + s11 * v.y() + s12 * v.z();
    z = s02 * v.x() + s12 * v.y() + s22 * v.z();
  }
};

// tₐᵀ A_k tᵦ for both matrices in a tangent frame.
struct TangentForms {
  Lanes q11, q12, q22;
};

EIGEN_ALWAYS_INLINE TangentForms tangent_forms(const SymmetricLanes& matrices,
                                               const geometry_detail::TangentFrame& frame) noexcept {
  const Eigen::Vector3d& t1 = frame.t1;
  const Eigen::Vector3d& t2 = frame.t2;
  Lanes x1, y1, z1, x2, y2, z2;
  matrices.image(t1, x1, y1, z1);
  matrices.image(t2, x2, y2, z2);
  return {x1 * t1.x() + y1 * t1.y() + z1 * t1.z(), x1 * t2.x() + y1 * t2.y() + z1 * t2.z(),
          x2 * t2.x() + y2 * t2.y() + z2 * t2.z()};
}

// The inverse shape matrices S_I, S_J and the centre offset.
struct PairData {
  SymmetricLanes shapes;
  Eigen::Vector3d offset;  // r = c_J − c_I

  [[nodiscard]] EIGEN_ALWAYS_INLINE AlongNormal along(const Eigen::Vector3d& unit_normal) const noexcept {
    AlongNormal value;
    value.normal = unit_normal;
    Lanes x, y, z;
    shapes.image(unit_normal, x, y, z);
    value.reach = (x * unit_normal.x() + y * unit_normal.y() + z * unit_normal.z()).sqrt();
    value.inverse_reach = value.reach.inverse();
    value.arm_x = x * value.inverse_reach;
    value.arm_y = y * value.inverse_reach;
    value.arm_z = z * value.inverse_reach;
    value.overlap = value.reach.sum() - unit_normal.dot(offset);
    value.gradient = Eigen::Vector3d(value.arm_x.sum(), value.arm_y.sum(), value.arm_z.sum()) - offset;
    return value;
  }
};

// v / |v| with one division (Eigen's normalized() divides each component).
[[nodiscard]] inline Eigen::Vector3d unit(const Eigen::Vector3d& v) noexcept { return v * (1.0 / std::sqrt(v.dot(v))); }

struct Solve {
  AlongNormal at;
  int steps = 0;
  bool converged = false;
};

// Tangential Hessian of ρ_I + ρ_J at n: Σ_k (tₐᵀ S_k t_b − (tₐ·a_k)(t_b·a_k)) / ρ_k.
struct Hessian2 {
  double h11;
  double h12;
  double h22;
};

EIGEN_ALWAYS_INLINE Hessian2 reach_hessian(const PairData& pair, const AlongNormal& at,
                                           const geometry_detail::TangentFrame& frame) noexcept {
  const TangentForms forms = tangent_forms(pair.shapes, frame);
  const Eigen::Vector3d& t1 = frame.t1;
  const Eigen::Vector3d& t2 = frame.t2;
  const Lanes a1 = at.arm_x * t1.x() + at.arm_y * t1.y() + at.arm_z * t1.z();
  const Lanes a2 = at.arm_x * t2.x() + at.arm_y * t2.y() + at.arm_z * t2.z();
  return {((forms.q11 - a1 * a1) * at.inverse_reach).sum(), ((forms.q12 - a1 * a2) * at.inverse_reach).sum(),
          ((forms.q22 - a2 * a2) * at.inverse_reach).sum()};
}

// The step where the Hessian H is not safely positive definite (the Levenberg-shifted step s is
// given): g is nearly flat or curved downwards along some tangent direction, as along the face of
// a flat body or across the rim of a thin one deeper in than its radius of curvature. The shifted
// step alone crawls there (length ≈ |∇g| / shift; 40 such steps were the `failed` of flat 1:100
// pairs, docs/geometry.md §6). So
//  1. for a negative eigenvalue λ of H the step gets a component t v along its unit eigenvector,
//     downhill, with t ≥ sqrt(10⁻¹² scale/|λ|): long enough that the predicted fall ½|λ|t² stands
//     well above the rounding of g (this also leaves a saddle with ∇g ≈ 0), and
//  2. after the usual halving until g does not rise, the step is doubled (up to 0.5 rad) while g
//     keeps falling, so a long flat valley takes a handful of evaluations, not hundreds of steps.
// Monotone in g like the Newton step. Pairs whose Hessian stays positive definite never come here.
// Returns false when no step lowers g (the solve gives up).
bool flat_or_saddle_step(const PairData& pair, const geometry_detail::TangentFrame& frame, const Hessian2& hessian,
                         double lowest, double scale, double s1, double s2, double length, AlongNormal& at) noexcept {
  const double g1 = frame.t1.dot(at.gradient);
  const double g2 = frame.t2.dot(at.gradient);
  if (lowest < 0.0) {
    // Eigenvector of λ: the larger of the two rows of (H − λ I), turned by 90°.
    const double row1 = std::abs(hessian.h11 - lowest) + std::abs(hessian.h12);
    const double row2 = std::abs(hessian.h22 - lowest) + std::abs(hessian.h12);
    double v1 = row1 >= row2 ? hessian.h12 : lowest - hessian.h22;
    double v2 = row1 >= row2 ? lowest - hessian.h11 : hessian.h12;
    const double norm = std::sqrt(v1 * v1 + v2 * v2);
    if (norm > 0.0 && std::isfinite(norm)) {
      const double sign = v1 * g1 + v2 * g2 > 0.0 ? -1.0 : 1.0;  // downhill (either way at a saddle)
      const double t = std::min(kMaxStep, std::max(length, std::sqrt(1e-12 * scale / -lowest)));
      v1 *= sign * t / norm;
      v2 *= sign * t / norm;
      s1 += v1;
      s2 += v2;
      length = std::sqrt(s1 * s1 + s2 * s2);
      if (length > kMaxStep) {
        s1 *= kMaxStep / length;
        s2 *= kMaxStep / length;
        length = kMaxStep;
      }
    }
  }
  const Eigen::Vector3d base = at.normal;
  const double base_overlap = at.overlap;
  bool accepted = false;
  for (int halving = 0; halving < 40 && !accepted; ++halving) {
    const AlongNormal trial = pair.along(unit(base + s1 * frame.t1 + s2 * frame.t2));
    if (trial.overlap <= base_overlap + 1e-15 * scale) {
      at = trial;
      accepted = true;
    } else {
      s1 *= 0.5;
      s2 *= 0.5;
      length *= 0.5;
    }
  }
  if (!accepted) return false;
  while (length < kMaxStep) {
    const double factor = std::min(2.0, kMaxStep / length);
    s1 *= factor;
    s2 *= factor;
    length *= factor;
    const AlongNormal trial = pair.along(unit(base + s1 * frame.t1 + s2 * frame.t2));
    if (!(trial.overlap < at.overlap)) break;
    at = trial;
  }
  return true;
}

// Damped Newton on the unit sphere for a local minimum of g. Monotone in g.
Solve common_normal(const PairData& pair, const AlongNormal& start, double final_step) noexcept {
  Solve solve;
  solve.at = start;
  const double scale = solve.at.reach.sum();
  const double gradient_tolerance = kGradientTolerance * scale;
  while (true) {
    const AlongNormal& at = solve.at;
    const auto frame = geometry_detail::tangent_frame(at.normal);
    const double g1 = frame.t1.dot(at.gradient);
    const double g2 = frame.t2.dot(at.gradient);
    const double gradient_norm = std::sqrt(g1 * g1 + g2 * g2);
    if (!std::isfinite(gradient_norm)) return solve;
    if (gradient_norm <= gradient_tolerance) {
      solve.converged = true;
      return solve;
    }
    if (solve.steps == kMaxNewtonSteps) return solve;
    ++solve.steps;

    // Riemannian Hessian on the sphere: ∇²ρ_I + ∇²ρ_J (tangential) − g I.
    const Hessian2 reach = reach_hessian(pair, at, frame);
    const double h11 = reach.h11 - at.overlap;
    const double h12 = reach.h12;
    const double h22 = reach.h22 - at.overlap;
    // Levenberg shift where the Hessian is not safely positive definite.
    const double size = std::abs(h11) + std::abs(h22) + std::abs(h12);
    const double half_split = 0.5 * (h11 - h22);
    const double lowest = 0.5 * (h11 + h22) - std::sqrt(half_split * half_split + h12 * h12);
    const double shift = lowest > 1e-8 * size ? 0.0 : 1e-3 * size - lowest + 1e-300;
    const double d11 = h11 + shift;
    const double d22 = h22 + shift;
    const double inverse_determinant = 1.0 / (d11 * d22 - h12 * h12);
    double s1 = -(d22 * g1 - h12 * g2) * inverse_determinant;
    double s2 = -(d11 * g2 - h12 * g1) * inverse_determinant;
    double length = std::sqrt(s1 * s1 + s2 * s2);
    if (!std::isfinite(length)) return solve;
    if (length > kMaxStep) {
      s1 *= kMaxStep / length;
      s2 *= kMaxStep / length;
      length = kMaxStep;
    }
    if (length < kFullStep && shift == 0.0) {  // quadratic convergence region: no line search
      solve.at = pair.along(unit(at.normal + s1 * frame.t1 + s2 * frame.t2));
      if (length <= final_step) {  // the error left is O(length²)
        solve.converged = true;
        return solve;
      }
      continue;
    }
    if (shift != 0.0) {
      if (!flat_or_saddle_step(pair, frame, {h11, h12, h22}, lowest, scale, s1, s2, length, solve.at)) return solve;
      continue;
    }
    bool accepted = false;
    for (int halving = 0; halving < 40 && !accepted; ++halving) {
      const AlongNormal trial = pair.along(unit(at.normal + s1 * frame.t1 + s2 * frame.t2));
      if (trial.overlap <= at.overlap + 1e-15 * scale) {
        solve.at = trial;
        accepted = true;
        // A full Newton step (not damped, not shortened) this short ends the solve, as above.
        if (halving == 0 && length <= final_step) {
          solve.converged = true;
          return solve;
        }
      }
      s1 *= 0.5;
      s2 *= 0.5;
    }
    if (!accepted) return solve;
  }
}

void fill_support_geometry(const Ellipsoid& body_i, const Ellipsoid& body_j, const AlongNormal& at,
                           ContactGeometry& geometry) noexcept {
  geometry.normal = at.normal;
  geometry.overlap = at.overlap;
  geometry.surface_point_i = body_i.center() + at.arm(0);
  geometry.surface_point_j = body_j.center() - at.arm(1);
  geometry.point = 0.5 * (geometry.surface_point_i + geometry.surface_point_j);
}

void store_warm_start(const Eigen::Vector3d& normal, NarrowPhaseWarmStart& warm) noexcept {
  warm.normal = {normal.x(), normal.y(), normal.z()};
  warm.valid = true;
}

void mark_separated(const Ellipsoid& body_i, const Ellipsoid& body_j, const AlongNormal& at,
                    NarrowPhaseResult& result) noexcept {
  result.status = NarrowPhaseStatus::separated;
  fill_support_geometry(body_i, body_j, at, result.geometry);
  store_warm_start(at.normal, result.warm_start);
}

// A converged common normal that is physical: n points from I to J (else the overlap exceeds
// the bodies' reach along n, the "far side" stationary point) and everything is finite.
bool physical(const Solve& solve, const Eigen::Vector3d& offset) noexcept {
  return solve.converged && solve.at.normal.dot(offset) > 0.0 && std::isfinite(solve.at.overlap) &&
         solve.at.arm_x.allFinite() && solve.at.arm_y.allFinite() && solve.at.arm_z.allFinite();
}

// The solved common normal: contact (with curvatures and α) or, for g ≤ 0, separated.
void mark_solved(const Ellipsoid& body_i, const Ellipsoid& body_j, const AlongNormal& at, bool surface_curvatures,
                 NarrowPhaseResult& result) noexcept {
  if (!(at.overlap > 0.0)) {
    mark_separated(body_i, body_j, at, result);
    return;
  }
  result.status = NarrowPhaseStatus::contact;
  ELLC_ASSERT(std::abs(at.normal.squaredNorm() - 1.0) < 1e-12, "contact normal is not a unit vector");
  ELLC_ASSERT(std::isfinite(at.overlap), "contact overlap is not finite");
  ContactGeometry& geometry = result.geometry;
  fill_support_geometry(body_i, body_j, at, geometry);
  ELLC_ASSERT(geometry.point.allFinite(), "contact point is not finite");
  // Shape operators of both implicit surfaces (x − c)ᵀ M_w (x − c) = 1 in one tangent frame:
  // Wₐᵦ = tₐᵀ M_w tᵦ / |M_w (x − c)|, and at the point with normal ±n, 1/|M_w (x − c)| = ρ(n)
  // (Ellipsoid::curvature_in_frame, both bodies at once). Their sum is the relative curvature
  // tensor of eq. (5); each alone gives that side's principal curvatures.
  const auto frame = geometry_detail::tangent_frame(at.normal);
  const TangentForms forms = tangent_forms(SymmetricLanes(body_i.shape(), body_j.shape()), frame);
  const Lanes w11 = forms.q11 * at.reach;
  const Lanes w12 = forms.q12 * at.reach;
  const Lanes w22 = forms.q22 * at.reach;
  geometry.relative = relative_curvature_from_tensor(w11.sum(), w12.sum(), w22.sum());
  ELLC_ASSERT(std::isfinite(geometry.relative.a_sum) && std::isfinite(geometry.relative.b_sum) &&
                  geometry.relative.a_sum <= geometry.relative.b_sum,
              "relative curvature A, B of eq. (5) not finite or A > B");
  if (surface_curvatures) {
    geometry.curvature_i = curvature_from_shape_operator(w11[0], w12[0], w22[0], frame, at.normal);
    geometry.curvature_j = curvature_from_shape_operator(w11[1], w12[1], w22[1], frame, -at.normal);
    pair_principal_directions(geometry, at.normal);
  }
  store_warm_start(at.normal, result.warm_start);
}

}  // namespace

NarrowPhaseResult ellipsoid_contact(const Ellipsoid& body_i, const Ellipsoid& body_j, const NarrowPhaseWarmStart* warm,
                                    const NarrowPhaseOptions& options) noexcept {
  NarrowPhaseResult result;  // status failed until proven otherwise
  if (!body_i.valid() || !body_j.valid()) return result;
  const PairData pair{SymmetricLanes(body_i.inverse_shape(), body_j.inverse_shape()),
                      body_j.center() - body_i.center()};
  const double distance = pair.offset.norm();
  auto centre_line = [&]() -> Eigen::Vector3d {
    return distance > 0.0 ? Eigen::Vector3d(pair.offset * (1.0 / distance)) : body_i.rotation().col(0);
  };
  if (distance > body_i.bounding_radius() + body_j.bounding_radius()) {  // bounding spheres apart
    mark_separated(body_i, body_j, pair.along(centre_line()), result);
    return result;
  }

  if (warm != nullptr && warm->valid) {
    const Eigen::Vector3d start(warm->normal[0], warm->normal[1], warm->normal[2]);
    const double start_norm = start.norm();
    if (std::isfinite(start_norm) && start_norm > 0.0) {
      const AlongNormal at_start = pair.along(start * (1.0 / start_norm));
      if (at_start.overlap < 0.0) {  // still a separating axis
        mark_separated(body_i, body_j, at_start, result);
        return result;
      }
      const Solve solve = common_normal(pair, at_start, options.final_step);
      result.iterations += solve.steps;
      if (physical(solve, pair.offset)) {
        mark_solved(body_i, body_j, solve.at, options.surface_curvatures, result);
        return result;
      }
    }
  }

  // Cold start (or fallback): the Perram–Wertheim contact normal; concentric bodies use I's
  // thinnest axis.
  result.cold_start = true;
  Eigen::Vector3d start = centre_line();
  if (distance > 0.0) {
    const ContactFunctionResult contact_function = perram_wertheim(body_i, body_j, true, 1e-6);
    result.contact_function_iterations = contact_function.iterations;
    if (contact_function.separated) {
      // F > 1 proves g < 0 along this normal in exact arithmetic; at touching, F may exceed 1 by
      // a rounding while g is a rounding above 0: then the Newton solve decides (never a
      // `separated` with a positive overlap).
      const AlongNormal along = pair.along(contact_function.normal);
      if (along.overlap <= 0.0) {
        mark_separated(body_i, body_j, along, result);
        return result;
      }
    }
    start = contact_function.normal;
  } else {
    Eigen::Index thinnest = 0;
    body_i.semi_axes().minCoeff(&thinnest);
    start = body_i.rotation().col(thinnest);
  }
  Solve solve = common_normal(pair, pair.along(unit(start)), options.final_step);
  result.iterations += solve.steps;
  if (!physical(solve, pair.offset) && distance > 0.0) {  // last resort: from the line of centres
    solve = common_normal(pair, pair.along(centre_line()), options.final_step);
    result.iterations += solve.steps;
  }
  if (physical(solve, pair.offset)) {
    mark_solved(body_i, body_j, solve.at, options.surface_curvatures, result);
  } else {
    result.geometry.normal = centre_line();  // failed: zeroed geometry, normal = line of centres
  }
  return result;
}

}  // namespace ellc
