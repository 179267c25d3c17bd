#pragma once
// Energies of the normal law of one contact, for the energy balance of a DEM run.

#include "ellc/law/contact_constants.hpp"

namespace ellc {

// Elastic energy the law gives back on full unloading from (δ, δ_*): ∫ F dδ along the
// unloading branch (eq. 49) or along Hertz (eq. 10) when the contact never yielded.
[[nodiscard]] double recoverable_energy(const ContactConstants& constants, double overlap, double max_overlap) noexcept;

// Energy the law has dissipated plastically in a contact with history δ_*: the area between the
// loading curve and the unloading branch, ∫₀^δ* F_load dδ − ∫_δp^δ* F_UL dδ (0 while δ_* ≤ δ_Y).
// Depends on δ_* only, so purely elastic contacts dissipate exactly nothing, whatever the
// geometry does. Hertz part in closed form, the plastic part by Simpson's rule.
[[nodiscard]] double plastic_work(const ContactConstants& constants, double max_overlap) noexcept;

}  // namespace ellc
