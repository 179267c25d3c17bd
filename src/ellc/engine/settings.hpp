#pragma once
// Engine settings: the material, the contact model, the box and the walls.
// Units (docs/engine.md): µm, µN, µs, ng; stress MPa, energy pJ, density ng/µm³.

#include <Eigen/Core>

#include <array>
#include <cstddef>

#include "ellc/hertz/elliptic_hertz.hpp"
#include "ellc/law/transition_fit.hpp"
#include "ellc/material/material.hpp"

namespace ellc::engine {

enum class NormalModel {
  becker_kamlah,  // the elastoplastic law (src/ellc/law/contact_law.hpp)
  hertz,          // purely elastic: the same law with an unreachable yield stress
};

struct ContactSettings {
  Material material;                 // particles and walls (walls are of the particle material)
  HertzMode hertz = HertzMode::hale;
  LawParameters law;
  NormalModel normal_model = NormalModel::becker_kamlah;
  double damping_ratio = 0.05;       // ζ of the viscous normal (and tangential) dashpot
  double friction = 0.3;             // Coulomb µ between particles
  double wall_friction = 0.3;        // Coulomb µ against the walls
  // Ellipsoid pairs: a Newton step for the common normal shorter than this (rad) ends the solve
  // (NarrowPhaseOptions, narrow_phase.hpp). 10⁻³ takes one step per time step from the warm start,
  // leaving the normal within ~(its turn per step)² ≲ 10⁻⁶ rad; 10⁻⁹ solves to rounding (docs/engine.md).
  double narrow_phase_final_step = 1e-3;
};

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
};

struct EngineSettings {
  ContactSettings contact;
  Box box;
  double dt = 1e-3;                                     // µs
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();    // µm/µs²
  double drag_rate = 0.0;       // global viscous drag −γ m v (1/µs): settling only, 0 otherwise
  double skin = 0.0;            // neighbour-list skin (µm); 0 → 0.2 of the mean bounding radius (simulation.cpp)
  double max_speed = 1e3;       // µm/µs: above this a particle counts as runaway
  // Loops over fewer particles than this run on one thread (fork/join would cost more); the
  // results are the same either way. Tests set 0 to exercise the threads on small systems.
  std::size_t parallel_threshold = 512;
  // Skip the pairs proven apart (a bound on how far their points moved since they were found
  // apart is below their clearance then). The skipped test would have found them apart too, so
  // the results are the same bit for bit; tests switch it off to check exactly that.
  bool skip_proven_separated = true;
};

}  // namespace ellc::engine
