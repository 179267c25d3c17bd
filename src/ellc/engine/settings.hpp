#pragma once
// Engine settings: the material, the contact model, the box and the walls.
// Units (docs/engine.md): µm, µN, µs, ng; stress MPa, energy pJ, density ng/µm³.

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "ellc/contact/contact_model.hpp"
#include "ellc/material/material.hpp"

namespace ellc::engine {

// The engine's defaults of the shared contact model (src/ellc/contact/contact_model.hpp): ζ = 0.05
// for both dashpots, μ = 0.3, and one Newton step of the common normal per time step (10⁻³ rad:
// the normal then stays within ~(its turn per step)² ≲ 10⁻⁶ rad of the solution; docs/engine.md).
[[nodiscard]] inline ContactModel engine_contact_defaults() noexcept {
  ContactModel model;
  model.normal_damping = 0.05;
  model.tangential_damping = 0.05;
  model.friction = 0.3;
  model.narrow_phase_final_step = 1e-3;
  return model;
}

struct ContactSettings {
  Material material;  // the particles' (one species), or species 0's when `species` is given
  // Several species (docs/engine.md, "Several species"): the material of each, indexed by
  // ParticleSet::species; empty: one species of `material`. A pair of species k, l mixes the two
  // by eq. (3) and Y = min (make_interaction); the walls meet each species' own material.
  std::vector<Material> species;
  ContactModel model = engine_contact_defaults();  // particle–particle contacts
  double wall_friction = 0.3;                      // μ against the walls; otherwise the walls use `model`
  // The walls' material: rigid_material(), an elastic (or elastic–plastic) plate, or, when empty,
  // the particles' own material (a mirror-image half-space, the behaviour of earlier versions).
  std::optional<Material> wall_material;
};

// The material of each species: `species`, or {material} for one species.
[[nodiscard]] inline std::vector<Material> species_materials(const ContactSettings& contact) {
  return contact.species.empty() ? std::vector<Material>{contact.material} : contact.species;
}

// Periodic in x and y over [0, lx) × [0, ly); walls bound z.
struct Box {
  double lx = 1.0;
  double ly = 1.0;
};

// A plane z = position with its normal along +z (bottom, side = +1) or −z (top, side = −1),
// moving at a prescribed velocity along z.
struct Wall {
  double position = 0.0;
  double velocity = 0.0;
  int side = 1;
  Eigen::Vector3d force = Eigen::Vector3d::Zero();  // total contact force the particles exert on it
  double work = 0.0;  // work the wall has done on the particles since the start (trapezoidal in time)
};

struct EngineSettings {
  ContactSettings contact;
  Box box;
  double dt = 1e-3;                                   // µs
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();  // µm/µs²
  double drag_rate = 0.0;  // global viscous drag −γ m v (1/µs): settling only, 0 otherwise
  double skin = 0.0;       // neighbour-list skin (µm); 0 → 0.2 of the mean bounding radius (simulation.cpp)
  double max_speed = 1e3;  // µm/µs: above this a particle counts as runaway
  // Loops over fewer particles than this run on one thread (fork/join would cost more); the
  // results are the same either way. Tests set 0 to exercise the threads on small systems.
  std::size_t parallel_threshold = 512;
  // Skip the pairs proven apart (a bound on how far their points moved since they were found
  // apart is below their clearance then). The skipped test would have found them apart too, so
  // the results are the same bit for bit; tests switch it off to check exactly that.
  bool skip_proven_separated = true;
  // Each step runs on one thread or on omp_get_max_threads(), whichever the engine measures to be
  // faster (thread_count.hpp): on a machine where other processes keep cores busy, one thread.
  // false: always omp_get_max_threads(). The results are the same bit for bit either way.
  bool adaptive_threads = true;
  // With threads, the pair list is cut into one range per thread, balanced on measured time
  // (pair_partition.hpp). Tests fix the cuts here (fractions of the list, 0 < c_1 ≤ … < 1, one
  // fewer than the threads; empty: balanced) to force idle threads to take others' pairs. The
  // results are the same bit for bit either way.
  std::vector<double> fixed_pair_cuts{};
};

}  // namespace ellc::engine
