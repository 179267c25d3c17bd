#include "ellc/engine/particles.hpp"

#include <cmath>
#include <numbers>

#include "ellc/engine/rigid_body.hpp"

namespace ellc::engine {

double ellipsoid_volume(const Eigen::Vector3d& axes) noexcept { return 4.0 / 3.0 * std::numbers::pi * axes.prod(); }

void ParticleSet::add(std::uint32_t particle_id, const Eigen::Vector3d& axes, double density,
                      const Eigen::Vector3d& centre, const Eigen::Quaterniond& rotation, std::uint16_t species_index) {
  const double m = density * ellipsoid_volume(axes);
  id.push_back(particle_id);
  semi_axes.push_back(axes);
  mass.push_back(m);
  inertia.push_back(solid_ellipsoid_inertia(m, axes));
  mean_radius.push_back(std::cbrt(axes.prod()));
  bounding_radius.push_back(axes.maxCoeff());
  position.push_back(centre);
  orientation.push_back(rotation.normalized());
  velocity.emplace_back(Eigen::Vector3d::Zero());
  angular_velocity.emplace_back(Eigen::Vector3d::Zero());
  force.emplace_back(Eigen::Vector3d::Zero());
  torque.emplace_back(Eigen::Vector3d::Zero());
  species.push_back(species_index);
}

bool ParticleSet::all_spheres() const noexcept {
  for (const auto& axes : semi_axes)
    if (axes.x() != axes.y() || axes.x() != axes.z()) return false;
  return true;
}

double ParticleSet::total_volume() const noexcept {
  double volume = 0.0;
  for (const auto& axes : semi_axes) volume += ellipsoid_volume(axes);
  return volume;
}

}  // namespace ellc::engine
