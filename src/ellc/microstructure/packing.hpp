#pragma once
// A packing of ellipsoids as the microstructure analyses take it: centres, semi-axes and
// orientations, a box with a periodic flag per axis, and optionally the contacts. It is a plain
// description, independent of the engine: the scenario layer builds one from a DEM state
// (scenario/state_analysis.hpp), and read_packing_file() reads one written by ellc or by another
// tool (docs/microstructure.md, "Packing files").

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace ellc::microstructure {

struct PackingBox {
  Eigen::Vector3d lower = Eigen::Vector3d::Zero();
  Eigen::Vector3d upper = Eigen::Vector3d::Ones();
  std::array<bool, 3> periodic{false, false, false};  // x, y, z

  [[nodiscard]] Eigen::Vector3d lengths() const { return upper - lower; }
  [[nodiscard]] double volume() const { return lengths().prod(); }
};

// One contact between particles i and j (rows of the packing), at `point`, for the force network.
struct ContactRecord {
  std::uint32_t i = 0;
  std::uint32_t j = 0;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();     // contact point (world), for the height profiles
  Eigen::Vector3d centre_j = Eigen::Vector3d::Zero();  // centre of j's image that touches i (periodic boxes)
  double normal_force = 0.0;                           // µN, > 0 pushes the bodies apart
  double max_overlap = 0.0;                            // δ_*, µm
  int regime = 0;                                      // the law's Regime as an integer (law/contact_law.hpp)
};

struct Packing {
  std::vector<Eigen::Vector3d> centres;
  std::vector<Eigen::Vector3d> semi_axes;        // (a, b, c) along the body axes
  std::vector<Eigen::Quaterniond> orientations;  // body → world
  PackingBox box;
  std::vector<ContactRecord> contacts;  // may be empty: no contact profile or force network then

  [[nodiscard]] std::size_t size() const noexcept { return centres.size(); }
  // Σ (4/3) π a b c: the solid volume when the particles do not overlap.
  [[nodiscard]] double particle_volume() const;
  // The smallest semi-axis of all particles (the resolution is set against it).
  [[nodiscard]] double smallest_semi_axis() const;
};

// Throws InputError naming the row (1-based particle row of `source`) of the first particle with a
// non-finite centre, a semi-axis that is NaN or ≤ 0, or a zero or non-finite quaternion, and a
// box that is not finite with upper > lower, and a contact naming a particle that does not exist.
void validate_packing(const Packing& packing, const std::string& source);

// Packing files (CSV): '#' lines `# box_lower = x y z`, `# box_upper = x y z`,
// `# periodic = x y z` (each true/false), then a header `x,y,z,a,b,c,qw,qx,qy,qz` and one row per
// particle. The contacts, when present, are in a second file FILE_contacts.csv (same folder, the
// stem of FILE + "_contacts.csv") with the header `i,j,px,py,pz,jx,jy,jz,normal_force,max_overlap,regime`.
// read_packing_file validates (validate_packing) and throws InputError naming file, row and column.
[[nodiscard]] Packing read_packing_file(const std::string& path);
void write_packing_file(const std::string& path, const Packing& packing);
[[nodiscard]] std::string contacts_file_for(const std::string& packing_path);

}  // namespace ellc::microstructure
