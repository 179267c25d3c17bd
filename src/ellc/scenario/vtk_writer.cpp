#include "ellc/scenario/vtk_writer.hpp"

#include <fstream>
#include <stdexcept>

namespace ellc::scenario {

using engine::ParticleSet;
using engine::Simulation;

void write_vtk_frame(const std::string& path, const Simulation& simulation) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot open " + path + " for writing");
  const ParticleSet& p = simulation.particles();
  const std::size_t n = p.size();
  out.precision(9);
  out << "# vtk DataFile Version 3.0\n"
      << "ellc dem step " << simulation.step_count() << " time " << simulation.time() << " us\n"
      << "ASCII\nDATASET POLYDATA\nPOINTS " << n << " double\n";
  for (const auto& x : p.position) out << x.x() << ' ' << x.y() << ' ' << x.z() << '\n';
  out << "VERTICES " << n << ' ' << 2 * n << '\n';
  for (std::size_t slot = 0; slot < n; ++slot) out << "1 " << slot << '\n';
  out << "POINT_DATA " << n << "\nSCALARS id int 1\nLOOKUP_TABLE default\n";
  for (auto id : p.id) out << id << '\n';
  out << "SCALARS mean_radius double 1\nLOOKUP_TABLE default\n";
  for (double radius : p.mean_radius) out << radius << '\n';
  out << "VECTORS velocity double\n";
  for (const auto& v : p.velocity) out << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
  out << "VECTORS force double\n";
  for (const auto& f : p.force) out << f.x() << ' ' << f.y() << ' ' << f.z() << '\n';
  out << "TENSORS shape double\n";
  for (std::size_t slot = 0; slot < n; ++slot) {
    const Eigen::Matrix3d rotation = p.orientation[slot].toRotationMatrix();
    const Eigen::Matrix3d shape = rotation * p.semi_axes[slot].asDiagonal() * rotation.transpose();
    for (int row = 0; row < 3; ++row) out << shape(row, 0) << ' ' << shape(row, 1) << ' ' << shape(row, 2) << '\n';
  }
  if (!out) throw std::runtime_error("writing " + path + " failed");
}

}  // namespace ellc::scenario
