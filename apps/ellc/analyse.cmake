# `ellc analyse` (docs/microstructure.md); thread_policy.cpp is shared with `ellc dem`.
target_sources(ellc_cli PRIVATE ${CMAKE_CURRENT_LIST_DIR}/analyse_command.cpp ${CMAKE_CURRENT_LIST_DIR}/thread_policy.cpp)
