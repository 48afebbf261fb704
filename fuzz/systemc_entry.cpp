// libsystemc.so defines main(), which calls the program's sc_main(). A fuzzer's main() is
// libFuzzer's: the executable's own definition wins over the shared library's, but the library's
// reference to sc_main must still resolve when the harness links SystemC (profiles hold sc_time).
// Reaching this function means the program started in SystemC's main instead of libFuzzer's.
#include <systemc>

#include <cstdio>

int sc_main(int, char**) {
  std::fputs("fuzz: started through SystemC's main(); a fuzzer starts in libFuzzer's main()\n", stderr);
  return 1;
}
