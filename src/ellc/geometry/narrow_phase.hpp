#pragma once
// Ellipsoid–ellipsoid narrow phase: the common normal (docs/geometry.md).
//
// Overlap measure: the common normal. Two surface points p_I, p_J whose outward normals are
// anti-parallel (n and −n) and whose joining line is along n; δ = (p_I − p_J)·n. Equivalently,
// n is a stationary point on the unit sphere of the overlap along n,
//
//   g(n) = ρ_I(n) + ρ_J(n) − n·(c_J − c_I),   ρ_k(n) = sqrt(nᵀ S_k n),
//
// whose gradient is p_I(n) − p_J(n). Its minimum over n is the signed penetration depth (the
// shortest translation that separates the bodies; minus the distance when they are apart), the
// measure of the Hertz theory the law builds on. For two spheres it is R_I + R_J − |c_J − c_I|.
//
// Solve: Newton's method on the sphere (2×2 system in the tangent plane), Levenberg-damped where
// the Hessian is not positive definite, with a monotone line search on g, so it always descends
// and cannot diverge. Start: the warm-start normal of the previous step when given; otherwise
// (and as the fallback when the warm solve fails) the normal at the Perram–Wertheim contact
// point, found by a bracketed solve of a concave 1-D problem (contact_function.hpp). A last
// fallback starts on the line of centres. Anything that still does not converge, and any
// solution that is not physical (overlap beyond the bodies' reach, n·(c_J − c_I) ≤ 0), is
// reported as NarrowPhaseStatus::failed with a zeroed geometry, never NaN.
//
// noexcept, no allocation; ≈ 0.3 µs warm, ≈ 0.6 µs cold (CPU time; figures in docs/geometry.md §7).

#include <array>
#include <cstdint>

#include "ellc/geometry/contact_geometry.hpp"
#include "ellc/geometry/ellipsoid.hpp"

namespace ellc {

// Stored per pair by the engine between steps; value-initialised = cold start.
struct NarrowPhaseWarmStart {
  std::array<double, 3> normal{0.0, 0.0, 0.0};  // last common normal (world frame, I → J)
  bool valid = false;
};

enum class NarrowPhaseStatus : std::uint8_t { contact, separated, failed };

[[nodiscard]] constexpr const char* status_name(NarrowPhaseStatus status) noexcept {
  switch (status) {
    case NarrowPhaseStatus::contact: return "contact";
    case NarrowPhaseStatus::separated: return "separated";
    case NarrowPhaseStatus::failed: return "failed";
  }
  return "unknown";
}

// contact:   full geometry, overlap > 0.
// separated: normal = a separating axis, overlap ≤ 0 = the overlap along it (−gap; equal to minus
//            the distance when the Newton solve ran, a bound |overlap| ≤ distance when separation
//            was proven early), surface points = the support points along it, no curvatures.
// failed:    no convergence or invalid input; geometry zeroed (normal = line of centres).
struct NarrowPhaseResult {
  NarrowPhaseStatus status = NarrowPhaseStatus::failed;
  ContactGeometry geometry;
  int iterations = 0;                   // Newton steps on the sphere (all attempts)
  NarrowPhaseWarmStart warm_start;      // store and pass back next step
  int contact_function_iterations = 0;  // Perram–Wertheim λ iterations (0 when warm-started)
  bool cold_start = false;              // the Perram–Wertheim start was used
};

// How far the Newton solve goes. A full (undamped) Newton step of length s radians leaves an
// error in the normal of about s² (quadratic convergence), so a step shorter than `final_step` is
// taken and ends the solve. The default ends at the rounding floor. A DEM engine whose warm start
// is off by the normal's turn in one time step (~10⁻⁴–10⁻³ rad) may pass 10⁻³: one Newton step
// instead of two, an error in the normal of 10⁻⁸–10⁻⁶ rad, and the overlap, being stationary in
// n, off by only the rounding.
//
// `surface_curvatures` off skips each side's principal curvatures, directions and α (ContactGeometry
// keeps their defaults); the relative curvature A, B, all the law needs, is always filled.
struct NarrowPhaseOptions {
  double final_step = 1e-9;
  bool surface_curvatures = true;
};

[[nodiscard]] NarrowPhaseResult ellipsoid_contact(const Ellipsoid& body_i, const Ellipsoid& body_j,
                                                  const NarrowPhaseWarmStart* warm = nullptr,
                                                  const NarrowPhaseOptions& options = {}) noexcept;

// g(n) above for one unit axis n, with J's centre at c_I + `centre_offset` (a periodic image of J
// may sit elsewhere than body_j.center(); only J's shape S_J is used). g < 0 proves that n is a
// separating axis: the bodies are apart. The cheap test a caller holding last step's separating
// axis (the warm start of a separated pair) runs before paying for ellipsoid_contact().
// (Inline: the engine calls it for every near-miss pair of every step.)
[[nodiscard]] inline double overlap_along(const Ellipsoid& body_i, const Ellipsoid& body_j,
                                          const Eigen::Vector3d& centre_offset,
                                          const Eigen::Vector3d& unit_axis) noexcept {
  return body_i.support_radius(unit_axis) + body_j.support_radius(unit_axis) - unit_axis.dot(centre_offset);
}

}  // namespace ellc
