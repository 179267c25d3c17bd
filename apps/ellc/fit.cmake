# `ellc fit` (calibration, docs/calibration.md); needs the Ceres-based ellc::calibration library.
if(TARGET ellc_calibration)
  target_sources(ellc_cli PRIVATE ${CMAKE_CURRENT_LIST_DIR}/fit_command.cpp)
  target_link_libraries(ellc_cli PRIVATE ellc::calibration)
endif()
