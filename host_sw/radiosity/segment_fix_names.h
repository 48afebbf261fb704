// The segment fixes (segment_fixes.h) in words: their description and the one refusal both `run` and
// the design search make of a coordinate width (docs/radiosity.md, "Fixed-point acne and its fixes").
#pragma once

#include <string>

#include "host_sw/radiosity/segment_fixes.h"

namespace rc {

// "offset 2 LSB + neighbours (ring 1) + 11-bit coordinates (4 guard bits)"; "" without fixes.
std::string describe(const SegmentFixOptions& fixes);
// Why coordinate_bits does not apply at `bits` (coordinate_bits >= bits), in the words both `run` and the
// design search refuse it with: "must be below --bits (15): ..."; "" when it applies (or is off).
std::string coordinate_bits_problem(int bits, int coordinate_bits);

}  // namespace rc
