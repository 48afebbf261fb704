// Creates a software visibility backend by name; the board backend is built by the board runner.
#pragma once

#include <memory>
#include <string>

#include "host_sw/visibility.h"

namespace rc {

// "float" (double precision), "fixed" (the bit-exact pipeline arithmetic at `bits` fractional bits,
// every segment against every face, on the CPU) or "fast" (the same answers bit for bit, testing only
// the faces that could hit, on every core; docs/fast-visibility.md). Throws std::invalid_argument
// with the accepted names otherwise.
// `threads` (fast only): 0 = every core.
std::unique_ptr<VisibilityBackend> make_software_visibility(const std::string& name, int bits, int threads = 0);

}  // namespace rc
