# The command line as a newcomer meets it (issue 51), included from tests/CMakeLists.txt
# where aspects_cli_test, _aspects and _models are defined.

# A mistyped subcommand: the one meant, or the list of them (before: "A subcommand is
# required").
aspects_cli_test(unknown_subcommand_meant 2 "^aspects: unknown subcommand 'solv'; did you mean `solve`\\?$" --
                 ${_aspects} solv m.robot)
aspects_cli_test(unknown_subcommand_swapped 2 "^aspects: unknown subcommand 'plto'; did you mean `plot`\\?$" --
                 ${_aspects} plto out)
aspects_cli_test(unknown_subcommand_listed 2
                 "^aspects: unknown subcommand 'm\\.robot' \\(the subcommands: info, solve, query, path, plot, view, export, count, verify\\)$" --
                 ${_aspects} m.robot)
# Short options, real defaults and plot's formats in --help, option errors pointing to the
# subcommand's --help.
add_test(NAME cli.help_and_short_options
         COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/cli_help.sh ${_aspects} ${ASPECTS_TEST_ROBOTS_DIR}/prrp.robot)
set_tests_properties(cli.help_and_short_options PROPERTIES TIMEOUT 60 LABELS cli)
# check_cert DIR: the certificate `aspects solve --out DIR` wrote there.
add_test(NAME cli.check_cert_directory
         COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/check_cert_directory.sh ${_aspects}
                 $<TARGET_FILE:check_cert> ${ASPECTS_TEST_ROBOTS_DIR}/prrp.robot)
set_tests_properties(cli.check_cert_directory PROPERTIES TIMEOUT 60 LABELS cli)
# Model errors at the use, in the user's words; a file that cannot be opened says why,
# without a position (before: "4:9 ... (found under 'sqr')" and ":0:0: cannot open model file").
aspects_cli_test(model_periodic_at_use 2
                 "^.*bad_periodic_use\\.robot:6:14: error: periodic variable 'q' must appear only inside sin\\(\\) or cos\\(\\); 'q\\^2' uses it outside them$" --
                 ${_aspects} solve ${_models}/bad_periodic_use.robot)
aspects_cli_test(model_file_says_why 2
                 "^/nonexistent/none\\.robot: error: cannot open model file: No such file or directory$" --
                 ${_aspects} info /nonexistent/none.robot)
# The man pages made from --help by help2man (cmake/man_pages.cmake), present after a build.
add_test(NAME cli.man_pages
         COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/man_page.sh ${PROJECT_BINARY_DIR}/man ${_aspects})
set_tests_properties(cli.man_pages PROPERTIES TIMEOUT 30 LABELS cli)
