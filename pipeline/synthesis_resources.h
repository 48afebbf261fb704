// A synthesizer's counts turned into the resource figures the model uses (docs/pipeline.md, "Two
// sources of resources"; issue 38).
//
// Yosys (scripts/synthesize) counts LUTs, flip-flops and block multipliers of one pipeline per family,
// width and multiplier kind, before place and route; it packs nothing into slices and infers no
// shift-register LUTs for these families. The paper's figures are place-and-route slices. The bridge
// is one linear rule shared by every family and both multiplier kinds:
//     slices = per_lut * (LUTs + SRLs) + per_flip_flop * flip-flops
// fitted by least squares on the paper's published points (sec 5.2 table: 7/15/23/31 bits without
// block multipliers; Table 1: 7/15 with), each paired with the synthesizer's counts for the paper's
// family (Virtex-II) at the same width and kind. Why this rule: of the rules tried against the six
// points by leave-one-out (one factor on ceil(max(LUTs, FFs)/2), one per multiplier kind, a factor on
// LUTs + FFs, an intercept added), it has the smallest largest leave-one-out error (docs/pipeline.md
// gives the table). The leave-one-out errors are computed here, from the files, and reported with
// every use. Block multipliers are the synthesizer's count (a DSP48 on Virtex-4, a MULT18X18 on the
// others); the wrapper and the clock stay the paper's (the synthesizer reports no clock).
//
// Widths the synthesizer was not run at: LUTs and flip-flops linear between the nearest synthesised
// widths of the same family and kind (flagged interpolated; the block count is the wider neighbour's,
// the larger), and beyond the synthesised range from the two nearest (flagged extrapolated).
#pragma once

#include <string>
#include <vector>

#include "pipeline/fixed_format.h"
#include "profiles/synthesis_table.h"

namespace rc::pipeline {

// One published point of the paper: a pipeline's place-and-route slices.
struct PublishedSlices {
  int frac_bits = 0;
  bool block_multipliers = false;
  double slices = 0;
};

struct LeaveOneOutError {
  PublishedSlices point;
  double predicted = 0;       // by the rule fitted on the other points
  double relative_error = 0;  // (predicted - published) / published
};

struct SynthesisSliceFit {
  double per_lut = 0, per_flip_flop = 0;   // fitted on every published point
  std::vector<LeaveOneOutError> leave_one_out;
  double max_abs_leave_one_out = 0;         // largest |relative_error|
  double max_abs_fit_error = 0;             // largest |error| of the full fit on its own points
};

// The synthesizer's counts of one pipeline (after interpolation, if any).
struct SynthesisCounts {
  int frac_bits = 0;
  bool block_multipliers_used = false;
  int luts = 0, srls = 0, flip_flops = 0, block_multipliers = 0;
  bool interpolated = false;  // between synthesised widths
  bool extrapolated = false;  // beyond them
  std::string family;         // "xc2v"
};

class SynthesisResources {
 public:
  // `paper_part`: the part of the paper's device ("XC2V6000"), whose family's rows are paired with the
  // published points. Throws std::runtime_error naming `origin` when that family has no row at a
  // published point or fewer than three points pair up.
  static SynthesisResources build(const profiles::SynthesisTable& table, const std::vector<PublishedSlices>& published,
                                  const std::string& paper_part, const std::string& origin);

  // Counts for a device part ("XC4VSX55"; case-insensitive prefix match). Throws std::invalid_argument
  // naming the part and the families the file has, or the missing multiplier kind.
  SynthesisCounts counts(const std::string& part, FracBits bits, bool use_block_multipliers) const;
  int slices(const SynthesisCounts& counts) const;  // by the fitted rule, rounded
  const SynthesisSliceFit& fit() const { return fit_; }
  const std::string& synthesizer() const { return synthesizer_; }
  const std::string& origin() const { return origin_; }

 private:
  const profiles::SynthesisFamily& family_of(const std::string& part) const;
  std::vector<profiles::SynthesisFamily> families_;
  SynthesisSliceFit fit_;
  std::string synthesizer_, origin_;
};

}  // namespace rc::pipeline
