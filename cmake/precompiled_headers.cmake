# Precompiled headers for the libraries: the standard headers (and MPFI's, Boost's disjoint
# sets, nlohmann-json) that most files of theirs include, parsed twice (one header for core/
# and proofs/, one for results/, run/ and planning/) instead of once per file. The machine code
# of core/ and proofs/ is byte for byte the same with or without them. Not for check_cert:
# with link-time optimisation they changed the code of some of its functions (the order in
# which the compiler meets declarations), and its speed is measured. bench/RESULTS.md,
# "Issue 48: the first command's build time".
#
# ASPECTS_PCH=AUTO (the default) uses them unless a compiler launcher is set: ccache hits a
# precompiled header only with `sloppiness = pch_defines,time_macros` in its configuration
# (docs/development.md, "Build time"), so a ccache build keeps compiling as before.
set(ASPECTS_PCH AUTO CACHE STRING
    "Precompiled headers: ON, OFF, or AUTO (ON unless CMAKE_CXX_COMPILER_LAUNCHER is set)")
set_property(CACHE ASPECTS_PCH PROPERTY STRINGS AUTO ON OFF)
if(ASPECTS_PCH STREQUAL "AUTO")
  if(CMAKE_CXX_COMPILER_LAUNCHER)
    set(_aspects_pch OFF)
  else()
    set(_aspects_pch ON)
  endif()
elseif(ASPECTS_PCH)
  set(_aspects_pch ON)
else()
  set(_aspects_pch OFF)
endif()

set(_aspects_pch_headers <algorithm> <array> <cmath> <cstdint> <cstring> <functional> <map>
    <memory> <optional> <stdexcept> <string> <tuple> <unordered_map> <utility> <vector>
    <mpfi.h>)

# aspects_precompile_headers(TARGET [HEADER...]): the common list and the target's own.
function(aspects_precompile_headers target)
  if(_aspects_pch)
    target_precompile_headers(${target} PRIVATE ${_aspects_pch_headers} ${ARGN})
  endif()
endfunction()

# aspects_reuse_precompiled_headers(TARGET FROM): TARGET uses FROM's (the same compile
# flags): one precompiled header costs about as much as compiling three of their files.
function(aspects_reuse_precompiled_headers target from)
  if(_aspects_pch)
    target_precompile_headers(${target} REUSE_FROM ${from})
  endif()
endfunction()
