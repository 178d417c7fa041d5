# Engine tests (paper Section 4): unit tests of components/separation, acceptance on
# the paper's robots, and the independent soundness check.
function(aspects_engine_test name label timeout)
  add_executable(${name} ${name}.cpp)
  target_link_libraries(${name} PRIVATE aspects_engine GTest::gtest_main)
  target_include_directories(${name} PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
  target_compile_definitions(${name} PRIVATE ASPECTS_ROBOTS_DIR="${ASPECTS_TEST_ROBOTS_DIR}")
  gtest_discover_tests(${name}
    TEST_PREFIX "${name}."
    DISCOVERY_MODE PRE_TEST
    PROPERTIES TIMEOUT ${timeout} LABELS ${label})
endfunction()

aspects_engine_test(test_components core 60)
aspects_engine_test(test_generalized_aspects acceptance 600)
aspects_engine_test(test_independent_soundness acceptance 600)
aspects_engine_test(test_constraints acceptance 900)
