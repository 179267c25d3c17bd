ellc_add_benchmark(bench_dem ${CMAKE_CURRENT_LIST_DIR}/bench_dem.cpp)
