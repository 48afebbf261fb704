// --offset-lsb, --neighbour-rings and --coordinate-bits: the host-side fixes for fixed-point self-shadowing
// (host_sw/radiosity/segment_fixes.h; docs/radiosity.md, "Fixed-point acne and its fixes"); --t-guard: the
// guard band on the pipeline's t test (in the lanes; SegmentFixOptions::t_guard, 0..pipeline::kMaxTGuard).
#pragma once

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "host_sw/radiosity/radiosity.h"

namespace rc {

// Adds both options, parsed into `fixes` (its width is set later: resolve_segment_fixes).
void add_segment_fix_options(CLI::App& cmd, SegmentFixOptions& fixes);
// Refuses the options where they do not apply: both with a float pipeline (`float_arith`: the fixes
// are defined on the fixed-point grid), --offset-lsb with double-precision visibility (`double_visibility`:
// no LSB to count), --coordinate-bits with double precision or at or above --bits. Throws
// CLI::ValidationError naming the option.
void check_segment_fix_options(const CLI::App& cmd, bool float_arith, const std::string& arith_name, bool double_visibility,
                               int bits, int coordinate_bits);
// `fixes` with the width they act at: `bits` when the run has a fixed-point width, 0 (double) otherwise.
SegmentFixOptions resolve_segment_fixes(SegmentFixOptions fixes, bool fixed_width, int bits);
// "offset 2 LSB + neighbours (ring 1): 12345 host re-tests (0.01 per segment), 678 segments cleared", or "" without fixes.
std::string segment_fix_summary(const SegmentFixOptions& fixes, const SolverResult& result);
// report.json's "segment_fixes" (null without fixes).
nlohmann::ordered_json segment_fix_json(const SegmentFixOptions& fixes, const SolverResult& result);

}  // namespace rc
