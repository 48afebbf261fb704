// configs/pipeline_resources.json read at the profile edge: the paper's synthesis figures (Table 1,
// sec 5.4/5.5 designs) and the float pipeline's counting constants as typed rows, each row with
// its source. pipeline::ResourceModel (pipeline/resource_model.h) builds its model from this and
// checks what only it knows (widths, the 18x18 splitting, the two designs' consistency).
#pragma once

#include <string>
#include <vector>

namespace rc::profiles {

struct ResourcePoint {  // pipeline_with(out)_block_multipliers[i]
  int frac_bits = 0;
  double clock_mhz = 0, slices = 0;
  int block_multipliers = 0;  // read for the with-block-multipliers points only
  std::string source;
};

struct ResourceDesign {  // designs[i]: the wrapper with `lanes` lanes, as synthesised
  int lanes = 0, frac_bits = 0, slices = 0, block_multipliers = 0;
  bool block_multipliers_used = false;
  double clock_mhz = 0;
  std::string source;
};

struct SourcedCount {
  int value = 0;
  std::string source;
};

struct FloatFamilyRow {
  std::string name, part_prefix, block_multiplier, source;
  int operand_bits = 0;
};

struct ResourceTable {
  std::string device_name, device_source;
  int device_slices = 0, device_block_multipliers = 0;
  int block_operand_bits = 0;
  std::string block_source;
  int synthesis_limit_bits = 0;
  std::string synthesis_limit_source;
  std::vector<ResourcePoint> soft, hard;  // file order
  std::vector<ResourceDesign> designs;    // file order
  SourcedCount multipliers, sign_flips, add_subs, comparators, guard_bits, luts_per_slice, flip_flops_per_slice;
  std::vector<FloatFamilyRow> families;
};

// Throws std::runtime_error "pipeline resources <origin>: <problem>" (a missing key, a wrong type, an
// empty source) or the text's own error (io/json_text.h).
ResourceTable parse_resource_table(const std::string& text, const std::string& origin);
ResourceTable read_resource_table(const std::string& path);  // at most io::kProfileLimitBytes

}  // namespace rc::profiles
