// The gtest main of the timing test kit (rc2000tlm::testkit_main, brought in by rc2000tlm::testkit).
// libsystemc supplies main() and calls sc_main(), so the test binary starts here. SystemC elaborates
// once per process: this main refuses to run more than one test in one process (ctest runs each test
// on its own, through gtest_discover_tests; by hand, pick one with --gtest_filter). Listing the tests
// (--gtest_list_tests, what gtest_discover_tests does) runs none and is allowed.
#include <gtest/gtest.h>
#include <systemc>  // declares sc_main with C linkage

#include <cstdio>
#include <cstdlib>

namespace {

// gtest applies --gtest_filter inside RUN_ALL_TESTS, just before OnTestProgramStart: the count of
// selected tests is known there and not before.
class OneTestPerProcess : public ::testing::EmptyTestEventListener {
  void OnTestProgramStart(const ::testing::UnitTest& unit) override {
    const int selected = unit.test_to_run_count();
    if (selected <= 1) return;
    std::fprintf(stderr,
                 "error: this binary holds SystemC tests and SystemC elaborates once per process;\n"
                 "       %d tests were selected. Run one with --gtest_filter=Suite.Name, or use ctest.\n",
                 selected);
    std::fflush(nullptr);
    std::_Exit(2);  // before any test has elaborated anything: nothing to clean up
  }
};

}  // namespace

int sc_main(int argc, char** argv) {
  // SystemC prints a banner at exit unless this is set before the library reads it.
  setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "1", 0);
  ::testing::InitGoogleTest(&argc, argv);
  ::testing::UnitTest::GetInstance()->listeners().Append(new OneTestPerProcess);
  return RUN_ALL_TESTS();
}
