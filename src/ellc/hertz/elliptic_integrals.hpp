#pragma once
// Carlson's symmetric elliptic integrals. The complete integrals of the exact Hertz solution are
// written through them because K − E = (m/3)·R_D(0, 1−m, 1) has no cancellation as m → 0,
// whereas subtracting std::comp_ellint_1 and _2 loses all digits for nearly circular contacts.

namespace ellc::elliptic {

// R_F(x, y, z) = ½ ∫₀^∞ [(t+x)(t+y)(t+z)]^{-1/2} dt, for x, y, z ≥ 0 with at most one zero.
[[nodiscard]] double carlson_rf(double x, double y, double z) noexcept;

// R_D(x, y, z) = (3/2) ∫₀^∞ (t+x)^{-1/2} (t+y)^{-1/2} (t+z)^{-3/2} dt, z > 0.
[[nodiscard]] double carlson_rd(double x, double y, double z) noexcept;

}  // namespace ellc::elliptic
