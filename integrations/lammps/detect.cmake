# Shared by integrations/lammps, tests/lammps and bench/lammps.cmake (which are configured before
# integrations/lammps): sets ELLC_LAMMPS_AVAILABLE and ELLC_LAMMPS_SKIP_REASON, plus
# ELLC_MPIRUN and ELLC_MPIRUN_FLAGS for running lmp_ellc under MPI.
set(ELLC_LAMMPS_AVAILABLE OFF)
set(ELLC_LAMMPS_SKIP_REASON "")
find_package(LAMMPS CONFIG QUIET)
find_package(MPI QUIET COMPONENTS CXX)
find_package(fmt QUIET)
if(NOT ELLC_BUILD_LAMMPS)
  set(ELLC_LAMMPS_SKIP_REASON "ELLC_BUILD_LAMMPS is OFF")
elseif(NOT LAMMPS_FOUND OR NOT TARGET LAMMPS::lammps)
  set(ELLC_LAMMPS_SKIP_REASON "LAMMPS development files not found (Debian: liblammps-dev)")
elseif(NOT MPI_CXX_FOUND)
  set(ELLC_LAMMPS_SKIP_REASON "MPI not found (Debian: libopenmpi-dev openmpi-bin)")
elseif(NOT fmt_FOUND)
  set(ELLC_LAMMPS_SKIP_REASON "fmt not found; the LAMMPS headers need it (Debian: libfmt-dev)")
else()
  set(ELLC_LAMMPS_AVAILABLE ON)
endif()

set(ELLC_MPIRUN "${MPIEXEC_EXECUTABLE}")
set(ELLC_MPIRUN_FLAGS "")
if(ELLC_MPIRUN)
  execute_process(COMMAND ${ELLC_MPIRUN} --version OUTPUT_VARIABLE _ellc_mpirun_version ERROR_QUIET)
  if(_ellc_mpirun_version MATCHES "Open MPI|OpenRTE")
    # More ranks than cores on small CI machines; root inside containers.
    set(ELLC_MPIRUN_FLAGS --oversubscribe)
  endif()
endif()
# OpenMPI refuses to run as root without these (CI containers run as root).
set(ELLC_MPI_TEST_ENVIRONMENT "OMPI_ALLOW_RUN_AS_ROOT=1;OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1;OMPI_MCA_rmaps_base_oversubscribe=1")
