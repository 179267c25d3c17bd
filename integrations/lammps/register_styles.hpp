#pragma once
// Adds this project's styles to a LAMMPS instance, the way a LAMMPS binary registers its built-in
// ones: by name in force->pair_map and modify->fix_map, before any input is read.

#include <string>

namespace LAMMPS_NS {
class LAMMPS;
}

namespace ellc_lammps {

// numeric LAMMPS version (LAMMPS::num_ver) this integration was compiled against, e.g. 20210929.
[[nodiscard]] int built_against_version();

// Empty when `running` is the version built against; otherwise the error message.
[[nodiscard]] std::string version_mismatch(int running, int expected);

// Registers pair_style ellipsoid/bk and fix ellipsoid/bk/history. Stops with a LAMMPS error when
// the running LAMMPS is not the version this code was compiled against.
void register_styles(LAMMPS_NS::LAMMPS* lmp, int expected_version);

}  // namespace ellc_lammps
