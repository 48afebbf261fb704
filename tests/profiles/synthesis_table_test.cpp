// configs/synthesis_resources.json's reader (profiles/synthesis_table.h): errors name the file, the
// field and the limit.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "profiles/synthesis_table.h"

namespace rc::profiles {
namespace {

TEST(SynthesisTable, ParseErrorsNameTheFileAndTheField) {
  const auto error = [](const std::string& text) {
    try {
      (void)parse_synthesis_table(text, "s.json");
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string head = R"({"synthesizer": "y", "command": "c", "source": "s", "families": [)";
  EXPECT_NE(error(R"({"command": "c", "source": "s", "families": []})").find("missing \"synthesizer\""), std::string::npos);
  EXPECT_NE(error(head + R"({"family": "xc2v", "part_prefix": "XC2V", "block": [], "array": [{"frac_bits": 40, "luts": 1, "srls": 0, "flip_flops": 1, "block_multipliers": 0}]}]})")
                .find("families[0].array[0]: frac_bits 40 is outside 7..31"),
            std::string::npos);
  EXPECT_NE(error(head + R"({"family": "xc2v", "part_prefix": "XC2V", "block": [], "array": [{"frac_bits": 9, "luts": -1, "srls": 0, "flip_flops": 1, "block_multipliers": 0}]}]})")
                .find("\"luts\" is not a whole number"),
            std::string::npos);
  EXPECT_NE(error(head + R"({"family": "xc2v", "part_prefix": "XC2V", "block": [], "array": [{"frac_bits": 9, "luts": 1, "srls": 0, "flip_flops": 1, "block_multipliers": 0}, {"frac_bits": 9, "luts": 1, "srls": 0, "flip_flops": 1, "block_multipliers": 0}]}]})")
                .find("width 9 twice"),
            std::string::npos);
  EXPECT_NE(error(head + R"({"family": "xc2v", "part_prefix": "XC2V", "block": [], "array": []}]})").find("no synthesis rows"),
            std::string::npos);
  EXPECT_EQ(error(head + R"({"family": "xc2v", "part_prefix": "XC2V", "block": [], "array": [{"frac_bits": 9, "luts": 1, "srls": 0, "flip_flops": 1, "block_multipliers": 0}]}]})"),
            "no error");
}

TEST(SynthesisTable, TheGeneratedConfigReads) {
  const SynthesisTable t = read_synthesis_table(std::string(RC_SOURCE_DIR) + "/configs/synthesis_resources.json");
  EXPECT_NE(t.synthesizer.find("Yosys"), std::string::npos);
  ASSERT_EQ(t.families.size(), 3u);
  for (const SynthesisFamily& f : t.families) {
    EXPECT_FALSE(f.block.empty()) << f.family;
    EXPECT_FALSE(f.array.empty()) << f.family;
  }
}

}  // namespace
}  // namespace rc::profiles
