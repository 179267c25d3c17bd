#include "register_styles.hpp"

#include <library.h>

#include "compute_contacts.hpp"
#include "fix_contact_history.hpp"
#include "fix_wall_ellipsoid_bk.hpp"
#include "lammps_includes.hpp"
#include "pair_ellipsoid_bk.hpp"

namespace ellc_lammps {

namespace {
LAMMPS_NS::Pair* create_pair(LAMMPS_NS::LAMMPS* lmp) { return new PairEllipsoidBK(lmp); }
LAMMPS_NS::Fix* create_history(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg) {
  return new FixContactHistory(lmp, narg, arg);
}
LAMMPS_NS::Compute* create_contacts(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg) {
  return new ComputeEllipsoidContacts(lmp, narg, arg);
}
LAMMPS_NS::Fix* create_wall(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg) {
  return new FixWallEllipsoidBK(lmp, narg, arg);
}
}  // namespace

int built_against_version() { return ELLC_LAMMPS_VERSION; }

std::string version_mismatch(int running, int expected) {
  if (running == expected) return {};
  return "lmp_ellc was built against LAMMPS version " + std::to_string(expected) +
         " but is running with LAMMPS version " + std::to_string(running) +
         " (liblammps.so); rebuild ellc against the installed liblammps-dev";
}

void register_styles(LAMMPS_NS::LAMMPS* lmp, int expected_version) {
  if (std::string problem = version_mismatch(lammps_version(lmp), expected_version); !problem.empty())
    fail(lmp->error, FLERR, problem);
  (*lmp->force->pair_map)[PairEllipsoidBK::kStyle] = &create_pair;
  (*lmp->modify->fix_map)[FixContactHistory::kStyle] = &create_history;
  (*lmp->modify->fix_map)[FixWallEllipsoidBK::kStyle] = &create_wall;
  (*lmp->modify->compute_map)[ComputeEllipsoidContacts::kStyle] = &create_contacts;
}

}  // namespace ellc_lammps
