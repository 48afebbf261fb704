# rc2000tlm_add_timing_test(<target> <source>...): a gtest binary of SystemC timing tests linked with
# rc2000tlm::testkit (its main runs one test per process), each test registered with ctest on its own
# through gtest_discover_tests. Installed with the "testkit" component of find_package(rc2000tlm).
include(GoogleTest)
function(rc2000tlm_add_timing_test target)
  add_executable(${target} ${ARGN})
  target_link_libraries(${target} PRIVATE rc2000tlm::testkit)
  gtest_discover_tests(${target} PROPERTIES ENVIRONMENT "SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1" DISCOVERY_TIMEOUT 60)
endfunction()
