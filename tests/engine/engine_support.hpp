#pragma once
// Shared helpers of the engine tests: NMC settings for free bodies and colliding packings.

#include <cstdint>

#include "ellc/engine/simulation.hpp"
#include "support/nmc.hpp"

namespace ellc::engine::testing {

using ellc::test::kNmc;
inline constexpr double kScaledDensity = 4.7e-3 * 1000.0;  // ng/µm³

// Settings for a few free bodies: no damping, no friction, no gravity, far walls.
[[nodiscard]] EngineSettings free_settings(NormalModel model);

// A loose packing of `count` ellipsoids (r̂ = 4 µm ± 10 %, aspects 1:[0.5..2]:[0.5..2], density
// kScaledDensity) in the 42 µm × 42 µm box kCollidingBox, inserted above `floor` at the given
// solid fraction, each with a random velocity in [−1, 1]³ µm/µs: bodies that collide often.
// (Test data from the scenario layer's packing generator and its Random.)
inline constexpr Box kCollidingBox{42.0, 42.0};
[[nodiscard]] ParticleSet colliding_packing(std::size_t count, std::uint64_t seed, double insertion_fraction,
                                            double floor, std::uint64_t velocity_seed, bool spheres = false);

}  // namespace ellc::engine::testing
