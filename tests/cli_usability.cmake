# The command line as a newcomer meets it (issue 51), included from tests/CMakeLists.txt
# where aspects_cli_test, _aspects and _models are defined.

# A mistyped subcommand: the one meant, or the list of them (before: "A subcommand is
# required").
aspects_cli_test(unknown_subcommand_meant 2 "^aspects: unknown subcommand 'solv'; did you mean `solve`\\?$" --
                 ${_aspects} solv m.robot)
aspects_cli_test(unknown_subcommand_swapped 2 "^aspects: unknown subcommand 'plto'; did you mean `plot`\\?$" --
                 ${_aspects} plto out)
aspects_cli_test(unknown_subcommand_listed 2
                 "^aspects: unknown subcommand 'm\\.robot' \\(the subcommands: info, solve, query, path, plot, count, verify\\)$" --
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
