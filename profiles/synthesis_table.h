// configs/synthesis_resources.json read at the profile edge: what a synthesizer (Yosys, scripts/synthesize)
// used for one pipeline of rtl/mt_pipeline.v, per family and width, with and without block multipliers,
// as typed rows. pipeline::SynthesisResources (pipeline/synthesis_resources.h) turns these counts into
// the slices the model uses (a fit on the paper's published points) and checks what only it knows.
// The file is generated (`scripts/synthesize config` from docs/results/synthesis/synthesis.json), so its
// source is stated once for the whole file: the synthesizer's version and command.
#pragma once

#include <string>
#include <vector>

namespace rc::profiles {

struct SynthesisPoint {  // one Yosys run
  int frac_bits = 0;
  int luts = 0;               // 4-input LUTs of logic
  int srls = 0;               // shift-register LUTs (take a LUT's place)
  int flip_flops = 0;
  int block_multipliers = 0;  // MULT18X18 or DSP48
};

struct SynthesisFamily {
  std::string family;       // "xc2v", "xc3s", "xc4v" (Yosys's -family)
  std::string part_prefix;  // "XC2V": a device whose part starts so uses these rows
  std::vector<SynthesisPoint> block;  // with block multipliers, ascending width
  std::vector<SynthesisPoint> array;  // multipliers in slices (explicit partial-product arrays), ascending
};

struct SynthesisTable {
  std::string synthesizer;  // "Yosys 0.23 (git sha1 ...)"
  std::string command;      // the synth command, with F for the family
  std::string source;       // where the rows come from
  std::vector<SynthesisFamily> families;
};

// Throws std::runtime_error "synthesis resources <origin>: <problem>" (a missing key, a wrong type, a
// width outside 7..31 or given twice, a negative count, an empty family) or the text's own error.
SynthesisTable parse_synthesis_table(const std::string& text, const std::string& origin);
SynthesisTable read_synthesis_table(const std::string& path);  // at most io::kProfileLimitBytes

}  // namespace rc::profiles
