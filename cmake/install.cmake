# `cmake --install BUILD --prefix PREFIX` puts the datomsim command, the shared library, the
# public headers, the viewer's script and a CMake package config in PREFIX. A researcher's
# project then does:
#
#   find_package(datomsim CONFIG REQUIRED)
#   target_link_libraries(my_programs PRIVATE datomsim::datomsim)
#
# (docs/writing-programs.md; examples/ are such projects).
include(CMakePackageConfigHelpers)

set(DATOMSIM_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/datomsim)

install(
  TARGETS datomsim_shared
  EXPORT datomsimTargets
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(TARGETS datomsim RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY include/datomsim DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
# Where `view` looks for it from an installed binary or library: PREFIX/share/datomsim.
install(
  FILES ${PROJECT_BINARY_DIR}/bin/viewer.bundle.js
  DESTINATION ${CMAKE_INSTALL_DATADIR}/datomsim
  OPTIONAL)
# The actuator designs (docs/actuators.md) beside the viewer's script, in
# PREFIX/share/datomsim/actuators.
install(
  DIRECTORY ${PROJECT_SOURCE_DIR}/data/actuators
  DESTINATION ${CMAKE_INSTALL_DATADIR}/datomsim
  FILES_MATCHING
  PATTERN "*.json")
install(
  EXPORT datomsimTargets
  NAMESPACE datomsim::
  DESTINATION ${DATOMSIM_CMAKE_DIR})

configure_package_config_file(
  cmake/datomsimConfig.cmake.in ${PROJECT_BINARY_DIR}/datomsimConfig.cmake
  INSTALL_DESTINATION ${DATOMSIM_CMAKE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/datomsimConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/datomsimConfig.cmake
              ${PROJECT_BINARY_DIR}/datomsimConfigVersion.cmake DESTINATION ${DATOMSIM_CMAKE_DIR})
