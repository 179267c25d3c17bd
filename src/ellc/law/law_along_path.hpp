#pragma once
// The law along a prescribed overlap path, carrying δ_* from point to point. The history is
// kept through δ ≤ 0 here: a path describes one contact spot whose dent persists, as in the
// paper's load–unload–reload FE runs. (A DEM deletes history on separation; docs/model.md §5.)

#include <span>

#include "ellc/law/contact_law.hpp"

namespace ellc {

// Writes one result per overlap into `results` (same size). Returns the final δ_*.
inline double evaluate_along_path(const ContactConstants& constants, std::span<const double> overlaps,
                                  std::span<LawResult> results, double initial_max_overlap = 0.0) noexcept {
  double max_overlap = initial_max_overlap;
  UnloadingCurveCache unloading;  // the constants are fixed: one derivation per unloading episode
  const std::size_t count = overlaps.size() < results.size() ? overlaps.size() : results.size();
  for (std::size_t index = 0; index < count; ++index) {
    results[index] = evaluate_contact_cached(constants, overlaps[index], max_overlap, unloading);
    max_overlap = results[index].max_overlap;
  }
  return max_overlap;
}

}  // namespace ellc
