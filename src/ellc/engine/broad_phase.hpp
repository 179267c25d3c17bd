#pragma once
// Broad phase: a cell list on bounding spheres builds a Verlet neighbour list with a skin.
// Periodic in x and y (minimum image), open in z (the walls bound it).

#include <vector>

#include "ellc/engine/pair_map.hpp"
#include "ellc/engine/particles.hpp"
#include "ellc/engine/settings.hpp"

namespace ellc::engine {

// Candidate pairs whose bounding spheres come closer than R_i + R_j + skin, sorted by key.
// Positions must already lie in [0, lx) × [0, ly). Requires lx, ly ≥ 2 (2 R_max + skin) so
// that the minimum image is the only image in range (checked by the scenario reader).
// `threads`: how many threads build it (≤ 1: the calling thread alone); the list is the same for
// any count.
[[nodiscard]] std::vector<PairSlot> find_candidate_pairs(const ParticleSet& particles, const Box& box, double skin,
                                                         int threads = 1);
// The same into `pairs` (cleared first), reusing its storage: the engine keeps a spare list so
// that a rebuild does not allocate (and page-fault in) a fresh one of ~250 bytes per pair.
void find_candidate_pairs(const ParticleSet& particles, const Box& box, double skin, int threads,
                          std::vector<PairSlot>& pairs);

// Moves the histories of `previous` into `next` where the keys match (both sorted by key).
// Returns the plastic work and the tangential-spring energy of active contacts that dropped out
// of the list (dissipated; the caller books both with the plastic work), summed in list order:
// the same bits for any number of `threads` (over fixed chunks of `previous`; ≤ 1: this thread).
double carry_over_history(std::vector<PairSlot>& previous, std::vector<PairSlot>& next, int threads = 1);

// Wraps x and y into the periodic box.
void wrap_positions(ParticleSet& particles, const Box& box) noexcept;

}  // namespace ellc::engine
