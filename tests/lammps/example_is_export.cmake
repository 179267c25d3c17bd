# examples/lammps/in.calendering and calendering.data are `ellc export-lammps` of
# examples/calendering.toml: export again and compare (cmake -P, ctest lammps_calendering_example_is_export).
file(REMOVE_RECURSE ${WORK})
execute_process(COMMAND ${ELLC} export-lammps ${SOURCE}/examples/calendering.toml -o ${WORK} --name calendering
                RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "ellc export-lammps failed (${status})")
endif()
foreach(name in.calendering calendering.data)
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${WORK}/${name} ${SOURCE}/examples/lammps/${name}
                  RESULT_VARIABLE different)
  if(different)
    message(FATAL_ERROR "examples/lammps/${name} is not the export of examples/calendering.toml; regenerate it: "
                        "ellc export-lammps examples/calendering.toml -o examples/lammps --name calendering")
  endif()
endforeach()
message(STATUS "examples/lammps/in.calendering and calendering.data are the export of examples/calendering.toml")
