ellc_add_benchmark(bench_geometry ${CMAKE_CURRENT_LIST_DIR}/bench_geometry.cpp)
