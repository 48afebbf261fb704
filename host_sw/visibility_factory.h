// Creates a software visibility backend by name; the board backend is built by the board runner.
#pragma once

#include <memory>
#include <string>

#include "host_sw/visibility.h"

namespace rc {

// "float" (double precision) or "fixed" (the bit-exact pipeline arithmetic at `bits` fractional
// bits, on the CPU). Throws std::invalid_argument with the accepted names otherwise.
std::unique_ptr<VisibilityBackend> make_software_visibility(const std::string& name, int bits);

}  // namespace rc
