#pragma once
// The Perram–Wertheim contact function of two ellipsoids (Perram & Wertheim 1985, J. Comput.
// Phys. 58, 409; Perram, Rasmussen, Præstgaard & Lebowitz 1996, Phys. Rev. E 54, 6565):
//
//   F(λ) = λ (1 − λ) rᵀ C(λ)⁻¹ r,   C(λ) = (1 − λ) S_I + λ S_J,   r = c_J − c_I,
//
// with S = R D² Rᵀ the inverse shape matrices. F is concave in λ ∈ [0, 1]; its maximum F* is the
// square of the factor by which both bodies must be scaled about their centres to just touch:
// F* < 1 overlapping, F* = 1 touching, F* > 1 separated. The maximiser is found by Newton's method
// safeguarded by the bracket [0, 1] (F' > 0 at 0, < 0 at 1), so it always converges. The common
// tangent point of the scaled bodies has the normal C(λ*)⁻¹ r: the narrow phase starts its
// common-normal Newton solve there when it has no warm start.
//
// F(λ) > 1 at any single λ already proves separation, and then n = C(λ)⁻¹ r is a separating axis
// (ρ_I(n) + ρ_J(n) − n·r < 0; derivation in docs/geometry.md), so the iteration can stop early.

#include <Eigen/Core>

#include "ellc/geometry/ellipsoid.hpp"

namespace ellc {

struct ContactFunctionResult {
  double value = 0.0;                                 // F(λ) at the last λ (= F* when converged)
  double lambda = 0.5;                                // λ
  Eigen::Vector3d normal = Eigen::Vector3d::UnitX();  // unit C(λ)⁻¹ r, from I towards J
  int iterations = 0;
  bool separated = false;  // F(λ) > 1 was seen: `normal` is a separating axis
  bool converged = false;  // λ* found to the tolerance (or separation proven)
};

// `stop_when_separated`: return as soon as F(λ) > 1 (the narrow phase only needs the certificate).
// `lambda_tolerance`: bracket width / Newton step in λ at which to stop (the narrow phase only
// needs a starting normal and uses 1e-6). Concentric bodies (r = 0) return value 0, converged = false.
[[nodiscard]] ContactFunctionResult perram_wertheim(const Ellipsoid& body_i, const Ellipsoid& body_j,
                                                    bool stop_when_separated = true,
                                                    double lambda_tolerance = 1e-12) noexcept;

}  // namespace ellc
