#pragma once
// Skipping pairs proven apart (docs/engine.md, "Pairs proven apart"), one rule for the built-in
// engine and the LAMMPS pair style. A separated pair may skip its narrow phase until the bounds on
// how far its two bodies have moved since together exceed the clearance it was found with; both
// sides of that comparison carry rounding, which these margins cover.

namespace ellc {

// The part of a separated pair's clearance later steps may spend: the clearance carries rounding
// of a few ulp of the bodies' size (reach: the sum of their bounding radii).
[[nodiscard]] constexpr double usable_clearance(double clearance, double reach) noexcept {
  return clearance - 1e-12 * reach;
}

// A body centre's computed displacement, inflated for the rounding of the computed motion.
[[nodiscard]] constexpr double bounded_displacement(double distance) noexcept { return distance * (1.0 + 1e-12); }

}  // namespace ellc
