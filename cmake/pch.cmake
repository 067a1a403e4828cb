# One precompiled header of the third-party and standard headers that the
# template-heavy translation units all parse (Eigen with its AutoDiff, the
# Ceres Jet, Boost.Odeint and Boost.Math, nlohmann-json, the standard
# library), compiled once and reused by every target. Measured on
# lagrangians/cyclotron.cc: 24.7 s without, 21.7 s with it.
#
# Clang only. A precompiled header must be compiled with its users'
# optimization level (__OPTIMIZE__ is one of its macros) and sanitizer
# flags: the sanitizer build, whose targets compile at -O0 or -O1
# (vivp_sanitizer_o1), has one of each, vivp_pch and vivp_pch_o1.
if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  return()
endif()

function(vivp_make_pch name)
  add_library(${name} OBJECT ${PROJECT_SOURCE_DIR}/cmake/pch.cc)
  target_link_libraries(${name} PRIVATE Eigen3::Eigen Ceres::ceres
                                        Boost::headers
                                        nlohmann_json::nlohmann_json)
  target_precompile_headers(${name} PRIVATE
    <algorithm> <array> <cmath> <functional> <iostream> <map> <memory>
    <sstream> <string> <variant> <vector>
    <Eigen/Dense> <unsupported/Eigen/AutoDiff> <ceres/jet.h>
    <boost/numeric/odeint.hpp>
    <boost/math/special_functions/ellint_1.hpp>
    <boost/math/special_functions/jacobi_elliptic.hpp>
    <nlohmann/json.hpp>)
endfunction()
vivp_make_pch(vivp_pch)
if(VIVP_SANITIZE)
  vivp_make_pch(vivp_pch_o1)
  vivp_sanitizer_o1(vivp_pch_o1)
endif()

# The header a target's files can reuse: under the sanitizers, the -O1 one
# for a target that vivp_sanitizer_o1 raised.
function(vivp_pch_for target out)
  set(pch vivp_pch)
  if(VIVP_SANITIZE)
    get_target_property(options ${target} COMPILE_OPTIONS)
    if(options AND "-O1" IN_LIST options)
      set(pch vivp_pch_o1)
    endif()
  endif()
  set(${out} ${pch} PARENT_SCOPE)
endfunction()
# Every C++ target below `dir` reuses it, the Lagrangians apart: for them
# the Makefile generator would list the header per source in the target's
# flags.make, so that adding one Lagrangian file rebuilt all of them
# (measured: 63.5 s instead of 17 s from saving a new file to its first
# `vivp converge`).
function(vivp_reuse_pch dir)
  get_property(targets DIRECTORY ${dir} PROPERTY BUILDSYSTEM_TARGETS)
  foreach(t IN LISTS targets)
    get_target_property(type ${t} TYPE)
    if(NOT t MATCHES "^(vivp_pch|vivp_pch_o1|vivp_lagrangians)$" AND type
       MATCHES "^(STATIC_LIBRARY|OBJECT_LIBRARY|EXECUTABLE)$")
      vivp_pch_for(${t} pch)
      target_precompile_headers(${t} REUSE_FROM ${pch})
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
  vivp_pch_for(vivp_lagrangians _pch_target)
  set(_pch ${CMAKE_BINARY_DIR}/CMakeFiles/${_pch_target}.dir/cmake_pch.hxx)
  target_compile_options(vivp_lagrangians PRIVATE -Winvalid-pch
    "SHELL:-Xclang -include-pch -Xclang ${_pch}.pch"
    "SHELL:-Xclang -include -Xclang ${_pch}")
  add_dependencies(vivp_lagrangians ${_pch_target})
  get_target_property(_sources vivp_lagrangians SOURCES)
  set_source_files_properties(${_sources} TARGET_DIRECTORY vivp_lagrangians
                              PROPERTIES OBJECT_DEPENDS ${_pch}.pch)
endif()
