#pragma once
// Elliptical Hertz contact (paper Sec. 2, docs/model.md §1). Two pieces:
//  * HertzShape: everything fixed by the curvatures alone (R_e, e, f1, f2), computed once per
//    contact configuration;
//  * HertzContact: the overlap-dependent quantities (contact semi-axes, p0, force).
// Hale's fit (eq. 4, 7) and the exact elliptic-integral solution share this interface: the exact
// mode defines f1, f2 through eq. (9) and (10), so every formula downstream is the same.

namespace ellc {

enum class HertzMode { hale, exact };

// Principal curvatures of one body at the contact point (1/length, convex > 0; a flat wall has 0).
struct PrincipalCurvatures {
  double kappa_1 = 0.0;
  double kappa_2 = 0.0;
};

// A and B of eq. (5), with B ≥ A (docs/model.md §1).
struct RelativeCurvature {
  double a_sum = 0.0;  // A
  double b_sum = 0.0;  // B
};

struct HertzShape {
  double equivalent_radius = 0.0;  // R_e = 1 / (2 sqrt(A B)), eq. (6)
  double eccentricity_sq = 0.0;    // e² = 1 − (b_c/a_c)², eq. (7)
  double f1 = 1.0;                 // correction factors, eq. (4) (Hale) or exact equivalents
  double f2 = 1.0;
  // c_c² = R_e δ f1²/f2 (eq. 9), so contact area per unit overlap / π.
  [[nodiscard]] double contact_radius_sq_per_overlap() const noexcept { return equivalent_radius * f1 * f1 / f2; }
};

struct HertzContact {
  double semi_axis_major = 0.0;            // a_c, eq. (8)
  double semi_axis_minor = 0.0;            // b_c, eq. (8)
  double equivalent_contact_radius = 0.0;  // c_c = sqrt(a_c b_c), eq. (9)
  double peak_pressure = 0.0;              // p0, eq. (2)
  double force = 0.0;                      // F_H, eq. (10)
};

// Eq. (5): A + B = ½ Σκ, B − A = ½ sqrt(Δ_I² + Δ_J² + 2 Δ_I Δ_J cos 2α), Δ_k = κ1^k − κ2^k.
// `alpha` is the angle between the κ1 directions of the two bodies.
[[nodiscard]] RelativeCurvature relative_curvature(PrincipalCurvatures body_i, PrincipalCurvatures body_j,
                                                   double alpha) noexcept;
// Eq. (5) in tensor form, for callers holding both bodies' curvature tensors (shape operators) in
// one tangent frame: their sum W has eigenvalues 2A and 2B. With W_k = R(θ_k) diag(κ1^k, κ2^k) R(θ_k)ᵀ
// and α = θ_I − θ_J, tr W = Σκ and (W₁₁ − W₂₂)² + 4 W₁₂² = Δ_I² + Δ_J² + 2 Δ_I Δ_J cos 2α, so this is
// eq. (5) term for term, without the principal directions or α.
[[nodiscard]] RelativeCurvature relative_curvature_from_tensor(double sum_11, double sum_12, double sum_22) noexcept;

// Which parts of the shape a caller needs. The law of one contact (eq. 9, 10 and the yield point)
// reads R_e, f1 and f2 only; e² gives the contact ellipse's axes (hertz_contact, the pressure
// patch). A DEM builds the shape per contact and step, and Hale's e² costs one exp or expm1 more.
enum class ShapeParts {
  all,           // R_e, e², f1, f2
  without_axes,  // R_e, f1, f2; e² is NaN for Hale's fit (the exact mode has it for free)
};

// R_e, e², f1, f2 for A ≤ B, A > 0. Hale: eq. (4), (7) with B/A ≥ 1. Exact: solves
// B/A = (E/k² − K)/(K − E) for k = b_c/a_c (Johnson 1985, Sec. 4.2). The parts computed are the
// same bits whichever `parts` asks for them.
[[nodiscard]] HertzShape hertz_shape(RelativeCurvature curvature, HertzMode mode,
                                     ShapeParts parts = ShapeParts::all) noexcept;

// Contact ellipse, p0 and F_H at overlap δ ≥ 0 for effective modulus E_e.
[[nodiscard]] HertzContact hertz_contact(const HertzShape& shape, double effective_modulus, double overlap) noexcept;

// p(x, y) of eq. (1) for a contact ellipse with semi-axes a_c (along x), b_c and peak p0.
[[nodiscard]] double hertz_pressure(double semi_axis_major, double semi_axis_minor, double peak_pressure, double x,
                                    double y) noexcept;

}  // namespace ellc
