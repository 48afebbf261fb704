# cmake --install: the libraries as rc2000tlm::<name> (rc2000tlm::tlm, rc2000tlm::board, ...), their
# headers under include/rc2000tlm/<folder>, the configs under share/rc2000tlm/configs (found at run
# time: io/config_dir.h), rc2000sim and its plot scripts (share/rc2000tlm/plots) when the apps are built,
# the timing test kit (rc2000tlm::testkit) when built, a CMake package (rc2000tlmConfig.cmake and
# its version file) and a pkg-config file (rc2000tlm.pc). examples/ builds against both
# (tests/scripts/install_test.sh).
include(CMakePackageConfigHelpers)
set(_rc_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/rc2000tlm)

install(DIRECTORY ${PROJECT_SOURCE_DIR}/configs/ DESTINATION ${CMAKE_INSTALL_DATADIR}/rc2000tlm/configs)
if(TARGET rc2000sim)
  install(TARGETS rc2000sim RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  # Its plot scripts, found beside the installed program (apps/plot.cpp, io/config_dir.h).
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/apps/plots/ DESTINATION ${CMAKE_INSTALL_DATADIR}/rc2000tlm/plots
          FILES_MATCHING PATTERN "*.py")
endif()

install(EXPORT rc2000tlmTargets NAMESPACE rc2000tlm:: DESTINATION ${_rc_cmake_dir})
# The timing test kit (testkit/): its own export set and pkg-config file, since it needs GTest, and
# rc2000tlm_add_timing_test (cmake/rc2000tlmTestkit.cmake), loaded with the "testkit" component.
if(RC_BUILD_TESTKIT)
  install(EXPORT rc2000tlmTestkitTargets NAMESPACE rc2000tlm:: DESTINATION ${_rc_cmake_dir})
  install(FILES ${CMAKE_CURRENT_LIST_DIR}/rc2000tlmTestkit.cmake DESTINATION ${_rc_cmake_dir})
endif()
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/rc2000tlmConfig.cmake.in
  ${PROJECT_BINARY_DIR}/rc2000tlmConfig.cmake INSTALL_DESTINATION ${_rc_cmake_dir} PATH_VARS CMAKE_INSTALL_DATADIR)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/rc2000tlmConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/rc2000tlmConfig.cmake ${PROJECT_BINARY_DIR}/rc2000tlmConfigVersion.cmake
  DESTINATION ${_rc_cmake_dir})

# pkg-config: every library, top layer first, so that one link line resolves them all (static).
get_property(_rc_libs GLOBAL PROPERTY RC_INSTALLED_LIBRARIES_rc2000tlmTargets)
list(REVERSE _rc_libs)
set(RC_PC_LIBS "")
foreach(_lib ${_rc_libs})
  string(APPEND RC_PC_LIBS " -l${_lib}")
endforeach()
file(RELATIVE_PATH RC_PC_TO_PREFIX ${CMAKE_INSTALL_FULL_LIBDIR}/pkgconfig ${CMAKE_INSTALL_PREFIX})
string(REGEX REPLACE "/$" "" RC_PC_TO_PREFIX "${RC_PC_TO_PREFIX}")
configure_file(${CMAKE_CURRENT_LIST_DIR}/rc2000tlm.pc.in ${PROJECT_BINARY_DIR}/rc2000tlm.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/rc2000tlm.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
if(RC_BUILD_TESTKIT)
  configure_file(${CMAKE_CURRENT_LIST_DIR}/rc2000tlm-testkit.pc.in ${PROJECT_BINARY_DIR}/rc2000tlm-testkit.pc @ONLY)
  install(FILES ${PROJECT_BINARY_DIR}/rc2000tlm-testkit.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
endif()
