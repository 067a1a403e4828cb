# One precompiled header of the third-party and standard headers that the
# template-heavy translation units all parse (Eigen with its AutoDiff, the
# Ceres Jet, Boost.Odeint and Boost.Math, nlohmann-json, the standard
# library), compiled once and reused by every target. Measured on
# lagrangians/cyclotron.cc: 24.7 s without, 21.7 s with it.
#
# Clang only, and not under the sanitizers: a precompiled header must be
# compiled with its users' optimization (-O0 there) and sanitizer flags.
if(VIVP_SANITIZE OR NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  return()
endif()

add_library(vivp_pch OBJECT ${PROJECT_SOURCE_DIR}/cmake/pch.cc)
target_link_libraries(vivp_pch PRIVATE Eigen3::Eigen Ceres::ceres
                                       Boost::headers
                                       nlohmann_json::nlohmann_json)
target_precompile_headers(vivp_pch PRIVATE
  <algorithm> <array> <cmath> <functional> <iostream> <map> <memory>
  <sstream> <string> <variant> <vector>
  <Eigen/Dense> <unsupported/Eigen/AutoDiff> <ceres/jet.h>
  <boost/numeric/odeint.hpp>
  <boost/math/special_functions/ellint_1.hpp>
  <boost/math/special_functions/jacobi_elliptic.hpp>
  <nlohmann/json.hpp>)

# Every C++ target below `dir` reuses it, the Lagrangians apart: for them
# the Makefile generator would list the header per source in the target's
# flags.make, so that adding one Lagrangian file rebuilt all of them
# (measured: 63.5 s instead of 17 s from saving a new file to its first
# `vivp converge`).
function(vivp_reuse_pch dir)
  get_property(targets DIRECTORY ${dir} PROPERTY BUILDSYSTEM_TARGETS)
  foreach(t IN LISTS targets)
    get_target_property(type ${t} TYPE)
    if(NOT t MATCHES "^(vivp_pch|vivp_lagrangians)$" AND type MATCHES
       "^(STATIC_LIBRARY|OBJECT_LIBRARY|EXECUTABLE)$")
      target_precompile_headers(${t} REUSE_FROM vivp_pch)
    endif()
  endforeach()
  get_property(subdirs DIRECTORY ${dir} PROPERTY SUBDIRECTORIES)
  foreach(sub IN LISTS subdirs)
    vivp_reuse_pch(${sub})
  endforeach()
endfunction()
vivp_reuse_pch(${PROJECT_SOURCE_DIR})

# The Lagrangians take it through target-wide flags instead, one line for
# every file, so that adding a file leaves flags.make as it was (1.3–1.4 s
# less per Lagrangian file: kepler.cc 5.2 → 3.9 s).
if(TARGET vivp_lagrangians)
  set(_pch ${CMAKE_BINARY_DIR}/CMakeFiles/vivp_pch.dir/cmake_pch.hxx)
  target_compile_options(vivp_lagrangians PRIVATE -Winvalid-pch
    "SHELL:-Xclang -include-pch -Xclang ${_pch}.pch"
    "SHELL:-Xclang -include -Xclang ${_pch}")
  add_dependencies(vivp_lagrangians vivp_pch)
  get_target_property(_sources vivp_lagrangians SOURCES)
  set_source_files_properties(${_sources} TARGET_DIRECTORY vivp_lagrangians
                              PROPERTIES OBJECT_DEPENDS ${_pch}.pch)
endif()
