#pragma once
// The unbalanced-force ratio, the static-equilibrium criterion of the protocol's hold and relax
// stages (docs/engine.md), from its four sums: written once here for every engine that reports it
// (Simulation::unbalanced_force_ratio; LAMMPS: fix wall/ellipsoid/bk's vector element 9).

#include <cstddef>

namespace ellc::engine {

// (Σ_particles |net contact force| / particles) / (Σ_contacts |contact force| / contacts): the
// mean magnitude of the particles' net contact force over the mean magnitude of the contact
// forces, pair and wall contacts alike (contacts overlapping below δ_p count, with no force). 0 in
// exact equilibrium; 0 without particles, 1 when no contact carries a force.
[[nodiscard]] constexpr double unbalanced_force_ratio(double net_force_sum, std::size_t particles,
                                                      double contact_force_sum, std::size_t contacts) noexcept {
  if (particles == 0) return 0.0;
  if (!(contact_force_sum > 0.0)) return 1.0;
  return (net_force_sum / static_cast<double>(particles)) / (contact_force_sum / static_cast<double>(contacts));
}

}  // namespace ellc::engine
