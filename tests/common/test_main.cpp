// Entry point of the test binaries that do not use SystemC (io, scenes, pipeline, radiosity, ...).
// libsystemc supplies main() and calls sc_main(), so they start here. The SystemC test binaries use
// the timing test kit's main instead (testkit/main/test_main.cpp: one test per process).
#include <gtest/gtest.h>
#include <systemc>  // declares sc_main with C linkage

#include <cstdlib>

int sc_main(int argc, char** argv) {
  // SystemC prints a banner at exit unless this is set before the library reads it.
  setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "1", 0);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
