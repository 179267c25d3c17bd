target_sources(ellc_cli PRIVATE ${CMAKE_CURRENT_LIST_DIR}/geometry_command.cpp)
