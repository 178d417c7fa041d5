# `cmake --install build --prefix P`: the two programs, the static libraries with their
# headers (P/include/aspects/), and a package config so that another project can
# `find_package(aspects)` and link `aspects::engine` (tests/downstream/ does).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set_target_properties(aspects_core PROPERTIES EXPORT_NAME core)
set_target_properties(aspects_engine PROPERTIES EXPORT_NAME engine)
set_target_properties(aspects_cert_writer PROPERTIES EXPORT_NAME cert_writer)

install(TARGETS aspects check_cert RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# Users include <aspects/NAME.h> (proofs/ and the writer) or <aspects/FOLDER/NAME.h>
# (core/'s layers, proofs/pipeline), as the headers include each other: P/include/aspects is on the path too.
install(TARGETS mpfi_deps arb_deps aspects_core aspects_engine aspects_cert_writer
        EXPORT aspectsTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} ${CMAKE_INSTALL_INCLUDEDIR}/aspects)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/core/ ${PROJECT_SOURCE_DIR}/proofs/
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/aspects FILES_MATCHING PATTERN "*.h")
install(FILES ${PROJECT_SOURCE_DIR}/certificates/certificate_writer.h
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/aspects)

set(_aspects_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/aspects)
install(EXPORT aspectsTargets NAMESPACE aspects:: DESTINATION ${_aspects_cmake_dir})
# The config looks for the same library names as this build (static archives first when
# ASPECTS_STATIC_MPFR is on).
string(REPLACE ";" " " ASPECTS_MP_NAMES_MPFI "${_mp_names_mpfi}")
string(REPLACE ";" " " ASPECTS_MP_NAMES_MPFR "${_mp_names_mpfr}")
string(REPLACE ";" " " ASPECTS_MP_NAMES_GMP "${_mp_names_gmp}")
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/aspectsConfig.cmake.in
  ${PROJECT_BINARY_DIR}/aspectsConfig.cmake INSTALL_DESTINATION ${_aspects_cmake_dir})
# 0.x: a minor version may change the API.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/aspectsConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/aspectsConfig.cmake ${PROJECT_BINARY_DIR}/aspectsConfigVersion.cmake
        DESTINATION ${_aspects_cmake_dir})
