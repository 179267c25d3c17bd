ellc_add_benchmark(bench_law ${CMAKE_CURRENT_LIST_DIR}/bench_law.cpp)
