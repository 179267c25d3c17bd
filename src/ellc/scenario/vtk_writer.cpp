#include "ellc/scenario/vtk_writer.hpp"

#include <fstream>
#include <stdexcept>
#include <vector>

namespace ellc::scenario {

using engine::ContactView;
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
  out << "SCALARS species int 1\nLOOKUP_TABLE default\n";  // index into [[species]] (0: one species)
  for (auto species : p.species) out << species << '\n';
  if (!out) throw std::runtime_error("writing " + path + " failed");
}

void write_vtk_contacts(const std::string& path, const Simulation& simulation) {
  std::vector<ContactView> contacts;
  simulation.for_each_contact([&](const ContactView& view) { contacts.push_back(view); });
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot open " + path + " for writing");
  const std::size_t n = contacts.size();
  out.precision(9);
  out << "# vtk DataFile Version 3.0\n"
      << "ellc dem contacts step " << simulation.step_count() << " time " << simulation.time() << " us\n"
      << "ASCII\nDATASET POLYDATA\nPOINTS " << 2 * n << " double\n";
  for (const ContactView& c : contacts)
    out << c.centre_i.x() << ' ' << c.centre_i.y() << ' ' << c.centre_i.z() << '\n'
        << c.other.x() << ' ' << c.other.y() << ' ' << c.other.z() << '\n';
  out << "LINES " << n << ' ' << 3 * n << '\n';
  for (std::size_t k = 0; k < n; ++k) out << "2 " << 2 * k << ' ' << 2 * k + 1 << '\n';
  if (n > 0) {  // without cells, no cell data
    out << "CELL_DATA " << n << '\n';
    const auto scalars = [&](const char* name, const char* type, auto&& value) {
      out << "SCALARS " << name << ' ' << type << " 1\nLOOKUP_TABLE default\n";
      for (const ContactView& c : contacts) out << value(c) << '\n';
    };
    scalars("normal_force", "double", [](const ContactView& c) { return c.normal_force; });
    scalars("overlap", "double", [](const ContactView& c) { return c.overlap; });
    scalars("max_overlap", "double", [](const ContactView& c) { return c.max_overlap; });
    scalars("regime", "int", [](const ContactView& c) { return static_cast<int>(c.regime); });
    scalars("size_ratio", "double", [](const ContactView& c) { return c.size_ratio; });
    scalars("wall", "int", [](const ContactView& c) { return c.wall; });
    out << "VECTORS force double\n";
    for (const ContactView& c : contacts) out << c.force.x() << ' ' << c.force.y() << ' ' << c.force.z() << '\n';
  }
  if (!out) throw std::runtime_error("writing " + path + " failed");
}

}  // namespace ellc::scenario
