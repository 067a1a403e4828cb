# vivp as a CMake package. `cmake --install build --prefix P` writes
#   P/include/vivp/<layer>/…   every header, included as in the tree
#                              ("solvers/variational/solve.h")
#   P/lib/                     the libraries and the object files of
#                              lagrangians/
#   P/bin/vivp                 the command line
#   P/lib/cmake/vivp/          vivpConfig.cmake for find_package(vivp)
# examples/ is a project of its own that uses the installed package;
# scripts/check-install.sh builds and runs it against a fresh install.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

# The libraries as vivp::NAME, in the tree (aliases) and installed (export
# names), so that a CMakeLists reads the same in both places.
set(_vivp_libraries core problems variational steppers bea spacetime distributed
                    solvers studies
                    scene report)
foreach(lib IN LISTS _vivp_libraries)
  add_library(vivp::${lib} ALIAS vivp_${lib})
  set_target_properties(vivp_${lib} PROPERTIES EXPORT_NAME ${lib})
endforeach()

# vivp::lagrangians: the registrations of lagrangians/, which nothing refers
# to, so they are linked as object files, never from an archive. A program
# gets an object library's files only when it links that library directly,
# and twice when it also gets them another way — each registration would then
# run twice, and the second ends the program (a name taken twice). So the
# object library is not linked by name outside the tree: vivp::lagrangians is
# an interface target that passes its files on as link items
# ($<TARGET_OBJECTS>, CMake ≥ 3.21), reaching a program once however many of
# its targets link it (vivp::vivp does).
add_library(vivp_lagrangians_linked INTERFACE)
target_link_libraries(vivp_lagrangians_linked INTERFACE
    vivp_lagrangians
    $<BUILD_INTERFACE:$<TARGET_OBJECTS:vivp_lagrangians>>
    $<INSTALL_INTERFACE:$<TARGET_OBJECTS:vivp::lagrangian_objects>>)
set_target_properties(vivp_lagrangians PROPERTIES
                      EXPORT_NAME lagrangian_objects)
set_target_properties(vivp_lagrangians_linked PROPERTIES
                      EXPORT_NAME lagrangians)
add_library(vivp::lagrangians ALIAS vivp_lagrangians_linked)

# vivp::vivp: all of it, the built-in Lagrangians included.
add_library(vivp_all INTERFACE)
target_link_libraries(vivp_all INTERFACE
    vivp_core vivp_problems vivp_solvers vivp_studies vivp_scene vivp_report
    vivp_lagrangians_linked)
set_target_properties(vivp_all PROPERTIES EXPORT_NAME vivp)
add_library(vivp::vivp ALIAS vivp_all)

set(VIVP_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/vivp)
list(TRANSFORM _vivp_libraries PREPEND vivp_ OUTPUT_VARIABLE _vivp_targets)
install(TARGETS ${_vivp_targets} vivp_lagrangians vivp_lagrangians_linked
                vivp_all
        EXPORT vivpTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        OBJECTS DESTINATION ${CMAKE_INSTALL_LIBDIR}/vivp
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/vivp)
install(TARGETS vivp RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY core problems solvers studies scene report lagrangians
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/vivp
        FILES_MATCHING PATTERN "*.h")
# The one generated header: the dimensions compiled into the libraries.
install(FILES ${VIVP_GENERATED_DIR}/core/action/precompiled_dims.h
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/vivp/core/action)
install(EXPORT vivpTargets NAMESPACE vivp::
        DESTINATION ${VIVP_INSTALL_CMAKEDIR})

configure_package_config_file(
  cmake/vivpConfig.cmake.in ${PROJECT_BINARY_DIR}/vivpConfig.cmake
  INSTALL_DESTINATION ${VIVP_INSTALL_CMAKEDIR})
# Before 1.0 a minor version may change the interface.
write_basic_package_version_file(
  ${PROJECT_BINARY_DIR}/vivpConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/vivpConfig.cmake
              ${PROJECT_BINARY_DIR}/vivpConfigVersion.cmake
              ${PROJECT_SOURCE_DIR}/cmake/inline_pointwise.cmake
        DESTINATION ${VIVP_INSTALL_CMAKEDIR})
