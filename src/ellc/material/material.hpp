#pragma once
// Material layer: isotropic elastic–ideally-plastic bodies and how two of them mix into the
// constants a contact sees. Unit-agnostic; docs use µm, MPa, µN.

#include <limits>
#include <string>

namespace ellc {

struct Material {
  double youngs_modulus = 0.0;  // E
  double poisson_ratio = 0.0;   // ν, in (−1, 0.5)
  double yield_stress = 0.0;    // Y, in simple tension
};

// What a contact needs from the two materials.
struct ContactMaterial {
  double effective_modulus = 0.0;  // E_e, paper eq. (3)
  double yield_stress = 0.0;       // Y of the contact: the softer body yields first (docs/model.md §5)
};

// Empty when valid; otherwise a sentence naming the field, its value and what was expected.
// `where` prefixes field names, e.g. "body_I.material".
[[nodiscard]] std::string validation_error(const Material& material, const std::string& where = "material");

// A body that neither deforms nor yields (a rigid plate or wall): E = Y = ∞. Eq. (3) then keeps
// the other body's compliance alone, E_e = E_I/(1 − ν_I²), and Y = Y_I. Not a valid input
// material (validation_error rejects infinite values); it is chosen by name.
[[nodiscard]] constexpr Material rigid_material() noexcept {
  return {std::numeric_limits<double>::infinity(), 0.0, std::numeric_limits<double>::infinity()};
}

// E_e = [ (1 − ν_I²)/E_I + (1 − ν_J²)/E_J ]⁻¹, paper eq. (3).
[[nodiscard]] double effective_modulus(const Material& body_i, const Material& body_j) noexcept;

// Y = min(Y_I, Y_J) (docs/model.md §5) together with E_e.
[[nodiscard]] ContactMaterial mix(const Material& body_i, const Material& body_j) noexcept;

}  // namespace ellc
