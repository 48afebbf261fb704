#include "apps/segment_fix_options.h"

#include <cstdio>
#include <string>

#include "apps/cli_options.h"
#include "host_sw/radiosity/segment_fix_names.h"
#include "pipeline/fixed_format.h"

namespace rc {

void add_segment_fix_options(CLI::App& cmd, SegmentFixOptions& fixes) {
  cmd.add_option("--offset-lsb", fixes.offset_lsb,
                 "Move every segment end K LSBs of --bits (of --coordinate-bits when given) along its face's normal, off the surface, before the pipeline "
                 "rounds it (host side, no hardware change; docs/radiosity.md, Fixed-point acne and its fixes)")
      ->check(CLI::Range(1, 1 << 20));
  cmd.add_option("--neighbour-rings", fixes.neighbour_rings,
                 "Own-surface rule extended to a mesh's neighbours: a segment is not blocked by faces sharing a vertex "
                 "with its start or end face (1) or with one of those (2); host-side re-tests, bit-exact at --bits")
      ->check(CLI::Range(1, 2));
  cmd.add_option("--coordinate-bits", fixes.coordinate_bits,
                 "Round every coordinate the pipeline receives to C fractional bits (C < --bits), so that the lanes "
                 "compute at --bits on coordinates of C bits: --bits - C guard bits in every product (docs/radiosity.md, "
                 "Fixed-point acne and its fixes)")
      ->check(CLI::Range(7, 30));
  cmd.add_option("--t-guard", fixes.t_guard,
                 "Guard band on the pipeline's t test, G LSBs: a segment counts as blocked by a face only for G < t*s < "
                 "|det| - G (0: the paper's test; at most " + std::to_string(pipeline::kMaxTGuard) +
                 ", the 8-bit T_GUARD register). In the lanes, not host side: bit-exact in every backend and on the board "
                 "(docs/radiosity.md, Fixed-point acne and its fixes)")
      ->check(CLI::Range(0, pipeline::kMaxTGuard));
}

void check_segment_fix_options(const CLI::App& cmd, bool float_arith, const std::string& arith_name, bool double_visibility,
                               int bits, int coordinate_bits) {
  if (float_arith) {
    refuse_given(cmd, {"--offset-lsb", "--neighbour-rings", "--coordinate-bits", "--t-guard"},
                 "does not apply with --arith " + arith_name + ": the fixes act on the fixed-point pipeline's grid (--bits)");
  } else if (double_visibility) {
    refuse_given(cmd, {"--offset-lsb", "--coordinate-bits", "--t-guard"},
                 "needs the fixed-point width (--bits); --visibility float (double precision) has none: use --visibility "
                 "fixed or fast, or --impl board");
  } else if (given(cmd, "--coordinate-bits") && !coordinate_bits_problem(bits, coordinate_bits).empty()) {
    refuse_option("--coordinate-bits", coordinate_bits_problem(bits, coordinate_bits));
  }
}

SegmentFixOptions resolve_segment_fixes(SegmentFixOptions fixes, bool fixed_width, int bits) {
  fixes.bits = fixed_width ? bits : 0;
  return fixes;
}

namespace {
std::string fix_name(const SegmentFixOptions& f) { return describe(f); }
}  // namespace

std::string segment_fix_summary(const SegmentFixOptions& fixes, const SolverResult& r) {
  if (!fixes.any()) return "";
  if (fixes.neighbour_rings == 0)
    return fix_name(fixes) + (fixes.t_guard != 0 ? ": no extra tests (the guard band is in the lanes' t test)" : ": host side, no extra tests");
  char text[256];
  std::snprintf(text, sizeof text, "%s: %llu host re-tests (%.3g per segment), %llu segments cleared", fix_name(fixes).c_str(),
                static_cast<unsigned long long>(r.fix_tests), r.segments ? double(r.fix_tests) / double(r.segments) : 0.0,
                static_cast<unsigned long long>(r.fix_cleared));
  return text;
}

nlohmann::ordered_json segment_fix_json(const SegmentFixOptions& fixes, const SolverResult& r) {
  if (!fixes.any()) return nullptr;
  return {{"offset_lsb", fixes.offset_lsb},
          {"neighbour_rings", fixes.neighbour_rings},
          {"coordinate_bits", fixes.coordinate_bits != 0 ? nlohmann::ordered_json(fixes.coordinate_bits) : nlohmann::ordered_json()},
          {"t_guard", fixes.t_guard},
          {"bits", fixes.bits != 0 ? nlohmann::ordered_json(fixes.bits) : nlohmann::ordered_json()},
          {"host_retests", r.fix_tests},
          {"segments_cleared", r.fix_cleared}};
}

}  // namespace rc
