# stepgen_bench: stepgen's maximum step rates and make-pulses cost (prints figures).
add_executable(stepgen_bench ${CMAKE_CURRENT_LIST_DIR}/stepgen_bench.cpp)
target_include_directories(stepgen_bench PRIVATE ${CMAKE_SOURCE_DIR}/kernel/components)
target_link_libraries(stepgen_bench PRIVATE ulapi)
