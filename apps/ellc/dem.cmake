target_sources(ellc_cli PRIVATE ${CMAKE_CURRENT_LIST_DIR}/dem_command.cpp)
