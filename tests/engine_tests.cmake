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

if(TARGET aspects)
  add_test(NAME cli.solve_outputs
           COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/solve_outputs.sh $<TARGET_FILE:aspects>
                   ${ASPECTS_TEST_ROBOTS_DIR}/prrp.robot $<TARGET_FILE:check_cert>)
  set_tests_properties(cli.solve_outputs PROPERTIES TIMEOUT 120 LABELS cli)
  aspects_cli_test(solve_progress 0 "\\[aspects\\] done: [0-9]+ boxes processed" --
                   $<TARGET_FILE:aspects> solve ${ASPECTS_TEST_ROBOTS_DIR}/rprpr.robot --progress --quiet)
  aspects_cli_test(solve_default_robot 0 "robot RRRRR" "CSNCs: [0-9]+, filtered: [0-9]+"
                   "lower bound on the number of aspects: [0-9]+" "time: " --
                   $<TARGET_FILE:aspects> solve --eps 1 --no-cert)
  set_tests_properties(cli.solve_default_robot PROPERTIES TIMEOUT 300)
  aspects_cli_test(solve_bad_threads 2 "--threads" -- $<TARGET_FILE:aspects> solve --threads -1)
  aspects_cli_test(solve_bad_bisect 2 "--bisect" -- $<TARGET_FILE:aspects> solve --bisect middle)
endif()

# Fuzzing (libFuzzer, clang): a bounded run of every target; skipped without clang++.
add_test(NAME fuzz.targets_20s
         COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/run_fuzz.sh 20 ${CMAKE_CURRENT_BINARY_DIR}/fuzz)
set_tests_properties(fuzz.targets_20s PROPERTIES TIMEOUT 600 LABELS fuzz)
if(TARGET aspects)
  aspects_cli_test(info_deep_nesting 2 "bad_deep_nesting\\.robot:4:[0-9]+: error: expression nested too deeply" --
                   $<TARGET_FILE:aspects> info ${CMAKE_CURRENT_SOURCE_DIR}/models/bad_deep_nesting.robot)
endif()

# The solver's and the checker's evaluators compared (the test links both; check_cert
# itself links neither core/ nor proofs/).
add_executable(test_evaluator_differential test_evaluator_differential.cpp
  ${PROJECT_SOURCE_DIR}/certificates/checker/model.cpp
  ${PROJECT_SOURCE_DIR}/certificates/checker/interval.cpp
  ${PROJECT_SOURCE_DIR}/certificates/checker/interval_doubles.cpp
  ${PROJECT_SOURCE_DIR}/certificates/checker/eval.cpp
  ${PROJECT_SOURCE_DIR}/certificates/checker/eval_speed.cpp)
target_link_libraries(test_evaluator_differential PRIVATE aspects_core GTest::gtest_main)
target_compile_definitions(test_evaluator_differential PRIVATE
  ASPECTS_ROBOTS_DIR="${ASPECTS_TEST_ROBOTS_DIR}")
gtest_discover_tests(test_evaluator_differential TEST_PREFIX "test_evaluator_differential."
  DISCOVERY_MODE PRE_TEST PROPERTIES TIMEOUT 120 LABELS core)

# The paper-reproduction pipeline in quick mode (the paper's eight robots and the full 3-RRR, coarse precisions,
# every certificate checked), so that it cannot rot.
add_test(NAME paper_repro.quick
         COMMAND ${PROJECT_SOURCE_DIR}/paper_repro/run_all.sh --quick --build ${PROJECT_BINARY_DIR}
                 --out ${CMAKE_CURRENT_BINARY_DIR}/paper_repro_quick)
set_tests_properties(paper_repro.quick PROPERTIES TIMEOUT 1200 LABELS "acceptance;slow")
# Without the full 3-RRR among the robots, the table and run_info.txt are still written.
add_test(NAME paper_repro.only_prrp
         COMMAND sh -c "\"$0\" --quick --only prrp --build \"$1\" --out \"$2\" && test -s \"$2/table1.md\" && test -s \"$2/run_info.txt\" && test ! -e \"$2/beyond_3rrr.md\""
                 ${PROJECT_SOURCE_DIR}/paper_repro/run_all.sh ${PROJECT_BINARY_DIR}
                 ${CMAKE_CURRENT_BINARY_DIR}/paper_repro_only_prrp)
set_tests_properties(paper_repro.only_prrp PROPERTIES TIMEOUT 120 LABELS cli)

# Certificate records held by the process that searched (MPI), fetched as it is written.
aspects_engine_test(test_held_records core 300)
target_link_libraries(test_held_records PRIVATE aspects_cert_writer)

# Two solves at once in one process, one MPFI only: each computes as it asked.
aspects_engine_test(test_two_solves core 300)

# Runs stopped after their search, each partial certificate checked by check_cert.
if(TARGET check_cert)
  aspects_engine_test(test_phase_stops core 300)
  target_link_libraries(test_phase_stops PRIVATE aspects_cert_writer)
  target_compile_definitions(test_phase_stops PRIVATE CHECK_CERT="$<TARGET_FILE:check_cert>")
  add_dependencies(test_phase_stops check_cert)
endif()
