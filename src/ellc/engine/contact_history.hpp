#pragma once
// What a contact remembers between steps, and the pair map that keeps it.
//
// The pair map is the Verlet neighbour list itself: a vector of pair slots sorted by the key
// (smaller particle id, larger id). Each slot carries its contact history; when the list is
// rebuilt the histories are carried over by merging old and new lists on the key, so they
// survive re-binning, position wrapping and any reordering of particle slots. History starts
// when the bodies first overlap (δ > 0) and is deleted when they separate (model-notes §5).

#include <Eigen/Core>

#include <cstdint>
#include <vector>

#include "ellc/law/contact_constants.hpp"

namespace ellc::engine {

using PairKey = std::uint64_t;

[[nodiscard]] constexpr PairKey pair_key(std::uint32_t id_i, std::uint32_t id_j) noexcept {
  return (static_cast<PairKey>(id_i) << 32) | id_j;
}

// Narrow-phase warm start, kept opaque to the engine: the previous solution's parameters.
struct WarmStart {
  double values[4] = {0.0, 0.0, 0.0, 0.0};
  bool valid = false;
};

struct ContactHistory {
  double max_overlap = 0.0;                                      // δ_*, the law's only history
  Eigen::Vector3d tangential_spring = Eigen::Vector3d::Zero();   // ξ, Mindlin history spring
  double last_overlap = 0.0;       // δ at the last evaluation (for the stored elastic energy)
  bool active = false;             // the bodies overlap (δ > 0)
  bool constants_cached = false;   // sphere pairs: constants built once per contact
  ContactConstants constants;      // cached for sphere pairs; the last constants otherwise
  WarmStart warm_start;
};

// One candidate pair of the neighbour list. `shift` is the periodic image offset added to the
// position of j; it is fixed between rebuilds.
struct PairSlot {
  PairKey key = 0;
  std::uint32_t i = 0;  // slots, with id[i] < id[j]
  std::uint32_t j = 0;
  Eigen::Vector3d shift = Eigen::Vector3d::Zero();
  ContactHistory history;
};

}  // namespace ellc::engine
