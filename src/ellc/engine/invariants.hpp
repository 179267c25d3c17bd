#pragma once
// Invariants of the engine's data structures, as predicates for ELLC_ASSERT (src/ellc/assert.hpp).
// Each is a full O(n) sweep; inside ELLC_ASSERT it runs only in Debug and sanitizer builds and is
// not evaluated at all in Release.

#include <cstdint>
#include <vector>

#include "ellc/engine/pair_map.hpp"
#include "ellc/engine/particles.hpp"
#include "ellc/engine/settings.hpp"

namespace ellc::engine::invariants {

// Strictly increasing keys: the order carry_over_history() merges on and every per-particle sum
// follows (results the same for any thread count).
[[nodiscard]] inline bool keys_sorted(const std::vector<PairSlot>& pairs) noexcept {
  for (std::size_t k = 1; k < pairs.size(); ++k)
    if (!(pairs[k - 1].key < pairs[k].key)) return false;
  return true;
}

// x, y in [0, lx) × [0, ly), as the broad phase's cell binning and minimum image assume. A
// non-finite position is skipped: the step's runaway check reports it by particle and step.
[[nodiscard]] inline bool positions_in_box(const ParticleSet& particles, const Box& box) noexcept {
  for (const auto& x : particles.position)
    if (x.allFinite() && !(x.x() >= 0.0 && x.x() < box.lx && x.y() >= 0.0 && x.y() < box.ly)) return false;
  return true;
}

// A neighbour list as the broad phase makes it: sorted by key, both slots valid, distinct,
// id[i] < id[j] and the key made of those ids.
[[nodiscard]] inline bool valid_pair_list(const std::vector<PairSlot>& pairs, const ParticleSet& particles) noexcept {
  const std::size_t count = particles.size();
  for (const PairSlot& pair : pairs) {
    if (pair.i >= count || pair.j >= count || pair.i == pair.j) return false;
    if (!(particles.id[pair.i] < particles.id[pair.j])) return false;
    if (pair.key != pair_key(particles.id[pair.i], particles.id[pair.j])) return false;
  }
  return keys_sorted(pairs);
}

// The per-particle index of the pair list (compressed rows): `start` has count + 1 entries from
// 0 to 2 × pairs; particle k's entries start[k] .. start[k+1] name pairs (entry >> 1) of which k
// is side i (entry even) or j (entry odd), each pair once per side, in pair-list order.
[[nodiscard]] inline bool valid_pair_index(const std::vector<PairSlot>& pairs, std::size_t count,
                                           const std::vector<std::uint32_t>& start,
                                           const std::vector<std::uint32_t>& entries) noexcept {
  if (start.size() != count + 1 || start.front() != 0 || start.back() != 2 * pairs.size()) return false;
  if (entries.size() != 2 * pairs.size()) return false;
  for (std::size_t slot = 0; slot < count; ++slot) {
    if (start[slot] > start[slot + 1]) return false;
    for (std::uint32_t k = start[slot]; k < start[slot + 1]; ++k) {
      const std::uint32_t entry = entries[k];
      if ((entry >> 1U) >= pairs.size()) return false;
      const PairSlot& pair = pairs[entry >> 1U];
      if (((entry & 1U) == 0U ? pair.i : pair.j) != slot) return false;
      if (k > start[slot] && !(entries[k - 1] < entry)) return false;
    }
  }
  return true;
}

}  // namespace ellc::engine::invariants
