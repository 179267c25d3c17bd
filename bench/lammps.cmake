# bench_lammps: pair_style ellipsoid/bk vs LAMMPS's pair_style granular (hertz/material) on the
# same dense packing, particle-timesteps/s (integrations/lammps/bench/bench_lammps.cpp); and the built-in
# engine vs granular on one sphere packing (SpheresEngineVsGranular, integrations/lammps/sphere_slab.hpp).
include(${PROJECT_SOURCE_DIR}/integrations/lammps/detect.cmake)
if(ELLC_LAMMPS_AVAILABLE)
  add_executable(bench_lammps ${PROJECT_SOURCE_DIR}/integrations/lammps/bench/bench_lammps.cpp)
  # ellc_lammps is defined in integrations/lammps, configured after bench/.
  target_link_libraries(bench_lammps PRIVATE ellc_lammps benchmark::benchmark)
endif()
