#include "ellc/microstructure/export.hpp"

#include <cstdint>
#include <fstream>

#include "ellc/io/input_error.hpp"

namespace ellc::microstructure {

namespace {

std::ofstream open_for_writing(const std::string& path, bool binary = false) {
  std::ofstream out(path, binary ? std::ios::binary : std::ios::out);
  if (!out) throw InputError(path, "output file", path, "a writable path (does its folder exist?)");
  out.precision(12);
  return out;
}

void check_written(const std::ofstream& out, const std::string& path) {
  if (!out) throw InputError(path, "output file", path, "a path with room to write it");
}

}  // namespace

void write_vti(const std::string& path, const VoxelGrid& grid) {
  std::ofstream out = open_for_writing(path, true);
  const std::string extent = "0 " + std::to_string(grid.shape[0]) + " 0 " + std::to_string(grid.shape[1]) + " 0 " +
                             std::to_string(grid.shape[2]);
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"ImageData\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
      << "  <ImageData WholeExtent=\"" << extent << "\" Origin=\"" << grid.origin.x() << ' ' << grid.origin.y() << ' '
      << grid.origin.z() << "\" Spacing=\"" << grid.spacing.x() << ' ' << grid.spacing.y() << ' ' << grid.spacing.z()
      << "\">\n"
      << "    <Piece Extent=\"" << extent << "\">\n"
      << "      <CellData Scalars=\"solid\">\n"
      << "        <DataArray type=\"UInt8\" Name=\"solid\" format=\"appended\" offset=\"0\"/>\n"
      << "      </CellData>\n    </Piece>\n  </ImageData>\n  <AppendedData encoding=\"raw\">\n   _";
  const std::uint64_t bytes = grid.solid.size();  // little-endian on every platform ellc builds for
  out.write(reinterpret_cast<const char*>(&bytes), sizeof bytes);
  out.write(reinterpret_cast<const char*>(grid.solid.data()), static_cast<std::streamsize>(grid.solid.size()));
  out << "\n  </AppendedData>\n</VTKFile>\n";
  check_written(out, path);
}

void write_npy(const std::string& path, const VoxelGrid& grid) {
  std::ofstream out = open_for_writing(path, true);
  // NPY format 1.0: magic, version, header length (uint16 LE), a dict padded with spaces to a
  // multiple of 64 bytes and ended by a newline, then the data (C order).
  std::string header = "{'descr': '|u1', 'fortran_order': False, 'shape': (" + std::to_string(grid.shape[2]) + ", " +
                       std::to_string(grid.shape[1]) + ", " + std::to_string(grid.shape[0]) + "), }";
  const std::size_t total = 10 + header.size() + 1;
  header.append((64 - total % 64) % 64, ' ');
  header += '\n';
  out.write("\x93NUMPY\x01\x00", 8);
  const auto length = static_cast<std::uint16_t>(header.size());
  const char length_bytes[2] = {static_cast<char>(length & 0xFF), static_cast<char>(length >> 8)};
  out.write(length_bytes, 2);
  out << header;
  out.write(reinterpret_cast<const char*>(grid.solid.data()), static_cast<std::streamsize>(grid.solid.size()));
  check_written(out, path);
}

void write_force_network_vtp(const std::string& path, const Packing& packing) {
  std::ofstream out = open_for_writing(path);
  out.precision(10);
  const std::size_t lines = packing.contacts.size();
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
      << "  <PolyData>\n    <Piece NumberOfPoints=\"" << 2 * lines << "\" NumberOfVerts=\"0\" NumberOfLines=\"" << lines
      << "\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n"
      << "      <Points>\n        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (const ContactRecord& c : packing.contacts) {
    const Eigen::Vector3d& a = packing.centres[c.i];
    out << a.x() << ' ' << a.y() << ' ' << a.z() << ' ' << c.centre_j.x() << ' ' << c.centre_j.y() << ' '
        << c.centre_j.z() << '\n';
  }
  out << "        </DataArray>\n      </Points>\n      <Lines>\n"
      << "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (std::size_t k = 0; k < lines; ++k) out << 2 * k << ' ' << 2 * k + 1 << '\n';
  out << "        </DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for (std::size_t k = 0; k < lines; ++k) out << 2 * (k + 1) << '\n';
  out << "        </DataArray>\n      </Lines>\n      <CellData Scalars=\"normal_force\">\n";
  const auto array = [&](const char* type, const char* name, const auto& value) {
    out << "        <DataArray type=\"" << type << "\" Name=\"" << name << "\" format=\"ascii\">\n";
    for (const ContactRecord& c : packing.contacts) out << value(c) << '\n';
    out << "        </DataArray>\n";
  };
  array("Float64", "normal_force", [](const ContactRecord& c) { return c.normal_force; });
  array("Float64", "max_overlap", [](const ContactRecord& c) { return c.max_overlap; });
  array("Int32", "regime", [](const ContactRecord& c) { return c.regime; });
  array("Int64", "particle_i", [](const ContactRecord& c) { return c.i; });
  array("Int64", "particle_j", [](const ContactRecord& c) { return c.j; });
  out << "      </CellData>\n    </Piece>\n  </PolyData>\n</VTKFile>\n";
  check_written(out, path);
}

void write_profile_csv(const std::string& path, const HeightProfile& profile) {
  std::ofstream out = open_for_writing(path);
  const bool voxels = !profile.porosity_voxels.empty();
  out << "z_low,z_high,z_mid,porosity_analytic" << (voxels ? ",porosity_voxels" : "")
      << ",contacts,mean_normal_force\n";
  for (std::size_t k = 0; k < profile.z_low.size(); ++k) {
    out << profile.z_low[k] << ',' << profile.z_high[k] << ',' << 0.5 * (profile.z_low[k] + profile.z_high[k]) << ','
        << profile.porosity_analytic[k];
    if (voxels) out << ',' << profile.porosity_voxels[k];
    out << ',' << profile.contacts[k] << ',' << profile.mean_normal_force[k] << '\n';
  }
  check_written(out, path);
}

void write_pore_size_csv(const std::string& path, const PoreSizeDistribution& psd) {
  std::ofstream out = open_for_writing(path);
  out << "# continuous pore-size distribution (Muench & Holzer 2008): cumulative_fraction = V(r), the pore "
         "fraction coverable by spheres of radius r in the pore; density = -dV/dr\n"
      << "# median_radius = " << psd.median_radius << "\n# largest_radius = " << psd.largest_radius << "\n"
      << "radius,cumulative_fraction,density\n";
  for (std::size_t k = 0; k < psd.radius.size(); ++k)
    out << psd.radius[k] << ',' << psd.cumulative_fraction[k] << ',' << psd.density[k] << '\n';
  check_written(out, path);
}

void write_force_distribution_csv(const std::string& path, const ForceDistribution& distribution) {
  std::ofstream out = open_for_writing(path);
  out << "# normal-force PDF of the particle contacts, f / <f> with <f> = " << distribution.mean_force << " uN over "
      << distribution.contacts << " contacts\n"
      << "f_over_mean_low,f_over_mean_high,pdf,count\n";
  for (std::size_t k = 0; k < distribution.density.size(); ++k)
    out << distribution.bin_low[k] << ',' << distribution.bin_high[k] << ',' << distribution.density[k] << ','
        << distribution.counts[k] << '\n';
  check_written(out, path);
}

}  // namespace ellc::microstructure
