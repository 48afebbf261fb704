// Entry point of every test binary. libsystemc supplies main() and calls sc_main(), so all test
// binaries start here. SystemC elaborates once per process: a binary built with RC_SYSTEMC_TESTS
// refuses to run more than one test in one process (ctest runs each test on its own, through
// gtest_discover_tests; by hand, pick one with --gtest_filter).
#include <gtest/gtest.h>
#include <systemc>  // declares sc_main with C linkage

#include <cstdio>
#include <cstdlib>

// SystemC prints a banner at exit unless this is set before the library reads it.
static const int kQuietSystemC = setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "1", 0);

int sc_main(int argc, char** argv) {
  (void)kQuietSystemC;
  ::testing::InitGoogleTest(&argc, argv);
#ifdef RC_SYSTEMC_TESTS
  const int selected = ::testing::UnitTest::GetInstance()->test_to_run_count();
  if (selected > 1) {
    std::fprintf(stderr,
                 "error: this binary holds SystemC tests and SystemC elaborates once per process;\n"
                 "       %d tests were selected. Run one with --gtest_filter=Suite.Name, or use ctest.\n",
                 selected);
    return 2;
  }
#endif
  return RUN_ALL_TESTS();
}
