// lmp_ellc: the LAMMPS executable of the installed liblammps, with the ellc styles registered.
// Same command line as `lmp` (-in, -var, -log, -screen, ...); run it under mpirun like lmp.

#include <mpi.h>

#include <cstdlib>
#include <string>

#include "lammps_includes.hpp"
#include "register_styles.hpp"

#include <input.h>

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  auto* lmp = new LAMMPS_NS::LAMMPS(argc, argv, MPI_COMM_WORLD);
  // ELLC_LAMMPS_EXPECT_VERSION replaces the built-in expectation (used by the test of the check).
  int expected = ellc_lammps::built_against_version();
  if (const char* forced = std::getenv("ELLC_LAMMPS_EXPECT_VERSION"); forced != nullptr) expected = std::atoi(forced);
  ellc_lammps::register_styles(lmp, expected);
  lmp->input->file();
  delete lmp;
  MPI_Barrier(MPI_COMM_WORLD);
  MPI_Finalize();
  return 0;
}
