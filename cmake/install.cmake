# cmake --install: the libraries as rc2000tlm::<name> (rc2000tlm::tlm, rc2000tlm::board, ...), their
# headers under include/rc2000tlm/<folder>, the configs under share/rc2000tlm/configs (found at run
# time: io/config_dir.h), rc2000sim when the apps are built, a CMake package (rc2000tlmConfig.cmake and
# its version file) and a pkg-config file (rc2000tlm.pc). examples/ builds against both
# (tests/scripts/install_test.sh).
include(CMakePackageConfigHelpers)
set(_rc_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/rc2000tlm)

install(DIRECTORY ${PROJECT_SOURCE_DIR}/configs/ DESTINATION ${CMAKE_INSTALL_DATADIR}/rc2000tlm/configs)
if(TARGET rc2000sim)
  install(TARGETS rc2000sim RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()

install(EXPORT rc2000tlmTargets NAMESPACE rc2000tlm:: DESTINATION ${_rc_cmake_dir})
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/rc2000tlmConfig.cmake.in
  ${PROJECT_BINARY_DIR}/rc2000tlmConfig.cmake INSTALL_DESTINATION ${_rc_cmake_dir} PATH_VARS CMAKE_INSTALL_DATADIR)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/rc2000tlmConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/rc2000tlmConfig.cmake ${PROJECT_BINARY_DIR}/rc2000tlmConfigVersion.cmake
  DESTINATION ${_rc_cmake_dir})

# pkg-config: every library, top layer first, so that one link line resolves them all (static).
get_property(_rc_libs GLOBAL PROPERTY RC_INSTALLED_LIBRARIES)
list(REVERSE _rc_libs)
set(RC_PC_LIBS "")
foreach(_lib ${_rc_libs})
  string(APPEND RC_PC_LIBS " -l${_lib}")
endforeach()
file(RELATIVE_PATH RC_PC_TO_PREFIX ${CMAKE_INSTALL_FULL_LIBDIR}/pkgconfig ${CMAKE_INSTALL_PREFIX})
string(REGEX REPLACE "/$" "" RC_PC_TO_PREFIX "${RC_PC_TO_PREFIX}")
configure_file(${CMAKE_CURRENT_LIST_DIR}/rc2000tlm.pc.in ${PROJECT_BINARY_DIR}/rc2000tlm.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/rc2000tlm.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
