target_sources(ellc_cli PRIVATE ${CMAKE_CURRENT_LIST_DIR}/export_lammps_command.cpp)
