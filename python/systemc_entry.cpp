// libsystemc.so calls sc_main from its own main(), which a Python process never runs; the symbol must
// still resolve when Python loads the module (it binds every symbol at load time), so it is exported
// although pybind11 hides the module's other symbols.
#include <systemc>

extern "C" __attribute__((visibility("default"))) int sc_main(int, char**) { return 1; }
