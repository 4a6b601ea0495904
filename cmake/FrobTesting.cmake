# One helper to add a test and one to add a benchmark (as MuJoCo's test/CMakeLists.txt does).
find_package(GTest REQUIRED)
find_package(benchmark REQUIRED)
include(GoogleTest)

# frob_add_test(name SOURCES a.cpp ... LIBS lib ... [TIMEOUT seconds] [LABELS label ...]): a GoogleTest
# executable whose tests ctest discovers one by one, each with a timeout so that a hang fails instead
# of stalling CI. Each label L gathers its executables in a target tests_L, so that a preset can build
# only what the labels it runs need.
function(frob_add_test name)
  cmake_parse_arguments(ARG "" "TIMEOUT" "SOURCES;LIBS;LABELS" ${ARGN})
  if(NOT ARG_TIMEOUT)
    set(ARG_TIMEOUT 120)
  endif()
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_LIBS} frob::build_options GTest::gtest GTest::gmock GTest::gtest_main)
  gtest_discover_tests(${name} DISCOVERY_TIMEOUT 60 PROPERTIES TIMEOUT ${ARG_TIMEOUT} LABELS "${ARG_LABELS}")
  foreach(label IN LISTS ARG_LABELS)
    if(NOT TARGET tests_${label})
      add_custom_target(tests_${label})
    endif()
    add_dependencies(tests_${label} ${name})
  endforeach()
endfunction()

# frob_add_benchmark(name SOURCES ... LIBS ...): a Google Benchmark executable. ctest runs it once
# with a minimal time (and FROB_BENCH_SMOKE set: fixed counts drop to one, tests/bench/iterations.hpp)
# so that benchmarks keep building and running; figures come from running it
# by hand (see README). A benchmark that calls SkipWithError still exits 0, so the smoke test also
# fails on the console reporter's "ERROR OCCURRED" line, and when the filter matches nothing.
function(frob_add_benchmark name)
  cmake_parse_arguments(ARG "" "" "SOURCES;LIBS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_LIBS} frob::build_options benchmark::benchmark benchmark::benchmark_main)
  add_test(NAME ${name}.smoke COMMAND ${name} --benchmark_min_time=0.0001 --benchmark_filter=.)
  set_tests_properties(${name}.smoke PROPERTIES TIMEOUT 300 LABELS bench ENVIRONMENT FROB_BENCH_SMOKE=1
    FAIL_REGULAR_EXPRESSION "ERROR OCCURRED;Failed to match any benchmarks")
endfunction()
