# vivp_inline_pointwise(TARGET <target>) or (SOURCES <files>...): a higher
# Clang inlining threshold for the translation units that compile a
# Lagrangian's pointwise derivatives (nested Eigen AutoDiffScalars,
# core/autodiff/pointwise.h): vivp's own Lagrangians and bench problems,
# and, through find_package(vivp), a program's file that registers its own.
#
# Why: at Clang's default threshold each expression of the density stays a
# call into an Eigen assignment of AutoDiffScalar vectors. At 1000 Clang 14
# inlines them: the Euler–Lagrange acceleration of the anharmonic oscillator
# (the predictor's right-hand side) 25 -> 8.5 ns a call; a uniform SBP84
# march of it, 1024 steps to t = 10, 5.5 -> 4.8 M instructions (callgrind,
# bench/small_solve_bench) and 0.31 -> 0.24 ms; the Kepler e = 0.9 march
# under error control at 1e-5 about 4 % less time (its window solves are
# mostly linear algebra). 500 inlines nothing more than the default, 2000
# nothing more than 1000. Compile time of those files +5-10 %
# (docs/performance.md §1).
# GCC 12 gains nothing from its inlining limits here (23 -> 22 ns), so it
# keeps its defaults; so does a sanitizer build (VIVP_SANITIZE), which is
# about compile time.
function(vivp_inline_pointwise)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang" OR VIVP_SANITIZE)
    return()
  endif()
  cmake_parse_arguments(ARG "" "TARGET" "SOURCES" ${ARGN})
  if(ARG_TARGET)
    target_compile_options(${ARG_TARGET} PRIVATE
                           "SHELL:-mllvm -inline-threshold=1000")
  endif()
  if(ARG_SOURCES)
    # A source's options are not de-duplicated, and SHELL: is not
    # understood there.
    set_property(SOURCE ${ARG_SOURCES} APPEND PROPERTY COMPILE_OPTIONS
                 -mllvm -inline-threshold=1000)
  endif()
endfunction()
