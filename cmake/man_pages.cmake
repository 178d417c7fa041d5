# Man pages aspects.1 and check_cert.1, made from the programs' --help by help2man (Debian's
# help2man, on README.md's install line) at build time, and installed into
# P/share/man/man1. Without help2man there are none (the test man.pages then fails).
find_program(HELP2MAN help2man)
if(NOT HELP2MAN)
  message(STATUS "help2man not found: no man pages (apt-get install help2man)")
  return()
endif()
set(ASPECTS_MAN_DIR ${PROJECT_BINARY_DIR}/man)
file(MAKE_DIRECTORY ${ASPECTS_MAN_DIR})
set(_man_script ${PROJECT_SOURCE_DIR}/cmake/man_page.sh)
add_custom_command(OUTPUT ${ASPECTS_MAN_DIR}/aspects.1
  COMMAND sh ${_man_script} ${HELP2MAN} $<TARGET_FILE:aspects> ${ASPECTS_MAN_DIR}/aspects.1
          "certified generalized aspects of parallel robots"
  DEPENDS aspects ${_man_script} VERBATIM)
add_custom_command(OUTPUT ${ASPECTS_MAN_DIR}/check_cert.1
  COMMAND sh ${_man_script} ${HELP2MAN} $<TARGET_FILE:check_cert> ${ASPECTS_MAN_DIR}/check_cert.1
          "independent checker of the certificates of aspects solve"
  DEPENDS check_cert ${_man_script} VERBATIM)
add_custom_target(man_pages ALL DEPENDS ${ASPECTS_MAN_DIR}/aspects.1 ${ASPECTS_MAN_DIR}/check_cert.1)
include(GNUInstallDirs)
install(FILES ${ASPECTS_MAN_DIR}/aspects.1 ${ASPECTS_MAN_DIR}/check_cert.1
        DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
