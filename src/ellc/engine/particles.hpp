#pragma once
// Particle state as structure of arrays: one vector per field, indexed by slot. A particle's
// persistent identity is `id`; contacts are keyed by ids, never by slots, so slots may be
// reordered without losing contact history.
//
// Units (docs/engine.md): length µm, force µN, time µs, mass ng, stress MPa, energy pJ.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>
#include <vector>

namespace ellc::engine {

struct ParticleSet {
  std::vector<std::uint32_t> id;
  std::vector<Eigen::Vector3d> semi_axes;  // (a, b, c) along the body axes
  std::vector<double> mass;
  std::vector<Eigen::Vector3d> inertia;  // principal moments of inertia, body frame
  std::vector<double> mean_radius;       // r̂ = (a b c)^{1/3}, paper eq. (50)
  std::vector<double> bounding_radius;   // largest semi-axis
  std::vector<Eigen::Vector3d> position;
  std::vector<Eigen::Quaterniond> orientation;  // body → world
  std::vector<Eigen::Vector3d> velocity;
  std::vector<Eigen::Vector3d> angular_velocity;  // body frame (Euler's equations)
  std::vector<Eigen::Vector3d> force;             // world frame, contacts only
  std::vector<Eigen::Vector3d> torque;            // world frame
  // The particle's species: an index into ContactSettings::species (settings.hpp), 0 in a
  // one-species packing. The per-pair contact constants are looked up by it, not stored here.
  std::vector<std::uint16_t> species;

  [[nodiscard]] std::size_t size() const noexcept { return id.size(); }
  // Appends a particle at rest; mass and inertia follow from the density (ng/µm³).
  void add(std::uint32_t particle_id, const Eigen::Vector3d& axes, double density, const Eigen::Vector3d& centre,
           const Eigen::Quaterniond& rotation, std::uint16_t species_index = 0);
  // True when every particle is a sphere (a = b = c): the engine then takes the sphere path.
  [[nodiscard]] bool all_spheres() const noexcept;
  [[nodiscard]] double total_volume() const noexcept;
};

// Ellipsoid volume (4/3) π a b c.
[[nodiscard]] double ellipsoid_volume(const Eigen::Vector3d& axes) noexcept;

}  // namespace ellc::engine
