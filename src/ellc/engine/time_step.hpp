#pragma once
// Critical time step from the Rayleigh-wave estimate (Li, Xu & Thornton 2005; the usual DEM
// bound): T_R = π r sqrt(ρ/G) / (0.1631 ν + 0.8766), with r the smallest semi-axis present (the
// stiffest, lightest configuration) and ρ the (possibly mass-scaled) density. The engine uses
// safety × T_R; 0.2 by default (docs/engine.md: why that covers plastic unloading stiffening).

#include "ellc/engine/particles.hpp"
#include "ellc/material/material.hpp"

namespace ellc::engine {

inline constexpr double kDefaultTimeStepSafety = 0.2;

[[nodiscard]] double rayleigh_time(double radius, double density, const Material& material) noexcept;

// safety × T_R of the smallest semi-axis in the set.
[[nodiscard]] double stable_time_step(const ParticleSet& particles, double density, const Material& material,
                                      double safety = kDefaultTimeStepSafety) noexcept;

}  // namespace ellc::engine
