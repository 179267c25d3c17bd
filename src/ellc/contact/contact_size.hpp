#pragma once
// c_c/r̂ of one contact: the size of its contact patch at the largest overlap it has reached
// (eq. 9 at δ_*) over the particle's mean radius r̂. The paper places the law's finite-deformation
// limit at c_c/r̂ = 0.16–0.4; both engines report contacts beyond 0.16 (docs/engine.md, "Validity").

#include <algorithm>
#include <cmath>

#include "ellc/law/contact_constants.hpp"

namespace ellc {

[[nodiscard]] inline double contact_size_ratio(const ContactConstants& constants, double max_overlap,
                                               double mean_radius) noexcept {
  return std::sqrt(constants.contact_radius_sq_per_overlap * std::max(max_overlap, 0.0)) / mean_radius;
}

}  // namespace ellc
