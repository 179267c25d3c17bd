#pragma once
// The pair map: the Verlet neighbour list itself, a vector of pair slots sorted by the key
// (smaller particle id, larger id). Each slot carries its contact's history record (the one
// LAMMPS stores too, src/ellc/contact/contact_history.hpp) and the engine's derived cache; when
// the list is rebuilt both are carried over by merging old and new lists on the key, so they
// survive re-binning, position wrapping and any reordering of particle slots.

#include <Eigen/Core>

#include <cstdint>

#include "ellc/contact/contact_history.hpp"

namespace ellc::engine {

using PairKey = std::uint64_t;

[[nodiscard]] constexpr PairKey pair_key(std::uint32_t id_i, std::uint32_t id_j) noexcept {
  return (static_cast<PairKey>(id_i) << 32) | id_j;
}

// One candidate pair of the neighbour list. `shift` is the periodic image offset added to the
// position of j; it is fixed between rebuilds.
struct PairSlot {
  PairKey key = 0;
  std::uint32_t i = 0;  // slots, with id[i] < id[j]
  std::uint32_t j = 0;
  Eigen::Vector3d shift = Eigen::Vector3d::Zero();
  ContactHistory history;
  ContactCache cache;
};

}  // namespace ellc::engine
