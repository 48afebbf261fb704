#include <gtest/gtest.h>

#include "board/design_fit.h"
#include "board/throughput_estimates.h"

#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "pipeline/float_format.h"

namespace rc::board {
namespace {

// Sec 5.6(a)'s accounting: three coordinate fields read and one result bit written.
TEST(ThroughputEstimates, BytesPerIntersectionFollowTheWordFormat) {
  EXPECT_DOUBLE_EQ(bytes_per_intersection(15), 3 * 2 + 0.125);  // two 16-bit fields per 32-bit word
  EXPECT_DOUBLE_EQ(bytes_per_intersection(7), 3 * 1 + 0.125);   // four 8-bit fields
  EXPECT_DOUBLE_EQ(bytes_per_intersection(23), 3 * 4 + 0.125);  // one field per word
}

// Sec 5.6 under the paper's own rule, from its printed figures only: Table 1's 15-bit
// block-multiplier pipeline (1976 slices, 30 multipliers, 176.9 MHz), the devices' slices and
// multipliers of sec 5.6(b), 6 banks x 4 bytes x 100 MHz and 6.125 bytes per intersection of
// sec 5.6(a), 52 MHz for the measured two-lane design (sec 5.7), and the peak software rate.
TEST(ThroughputEstimates, PaperRuleIsTheArithmeticOnThePapersPrintedInputs) {
  const double software = 5889.0 * 4480 * 1120 / 1459.8;  // Table 2: the largest scene's tests / software seconds
  const std::vector<PaperEstimate> e = paper_rule_estimates(software);
  ASSERT_EQ(e.size(), 4u);
  for (const PaperEstimate& x : e) {
    EXPECT_EQ(x.rule, EstimateRule::Paper);
    EXPECT_DOUBLE_EQ(x.bytes_per_intersection, 6.125);
    EXPECT_DOUBLE_EQ(x.speedup_vs_software, x.intersections_per_s / software);
  }
  EXPECT_EQ(e[0].estimate, "RC2000 bandwidth limit");
  EXPECT_DOUBLE_EQ(e[0].gb_per_s, 2.4);
  EXPECT_DOUBLE_EQ(e[0].intersections_per_s, 2.4e9 / 6.125);
  EXPECT_EQ(e[1].estimate, "measured 2-lane design");
  EXPECT_DOUBLE_EQ(e[1].intersections_per_s, 2 * 52e6);
  // Virtex-4 SX55: min(24576 / 1976, 512 / 30) = min(12, 17) = 12 lanes.
  EXPECT_EQ(e[2].device, "virtex4-sx55");
  EXPECT_EQ(e[2].lanes, 12);
  EXPECT_DOUBLE_EQ(e[2].clock_mhz, 176.9);
  EXPECT_DOUBLE_EQ(e[2].intersections_per_s, 12 * 176.9e6);
  EXPECT_DOUBLE_EQ(e[2].bytes_per_cycle, 12 * 6.125);
  EXPECT_NEAR(e[2].gb_per_s, 12 * 6.125 * 176.9e6 / 1e9, 1e-12);
  // Spartan-3 5000: min(33280 / 1976, 104 / 30) = min(16, 3) = 3 lanes.
  EXPECT_EQ(e[3].device, "spartan3-5000");
  EXPECT_EQ(e[3].lanes, 3);
  EXPECT_DOUBLE_EQ(e[3].intersections_per_s, 3 * 176.9e6);
  EXPECT_DOUBLE_EQ(e[3].bytes_per_cycle, 3 * 6.125);
}

// The same rule on any device: the XC2V6000 holds min(33792 / 1976, 144 / 30) = min(17, 4) = 4
// Table 1 pipelines; the model fits 8 lanes at 15 bits (4 with block multipliers, 4 without) and
// only 3 at 23 bits, which stream below their peak.
TEST(ThroughputEstimates, LanesThatFitOnAnyDevice) {
  const DeviceProfile v2 = find_device_profile("xc2v6000");
  const PaperEstimate paper = paper_rule_lanes_that_fit(v2, 2e7);
  EXPECT_EQ(paper.lanes, 4);
  EXPECT_DOUBLE_EQ(paper.intersections_per_s, 4 * 176.9e6);
  EXPECT_DOUBLE_EQ(paper.speedup_vs_software, 4 * 176.9e6 / 2e7);
  const PaperEstimate model15 = model_lanes_that_fit(v2, 2e7, 15);
  const PaperEstimate model23 = model_lanes_that_fit(v2, 2e7, 23);
  EXPECT_EQ(model15.lanes, 8);
  EXPECT_EQ(model23.lanes, 3);
  // The bound is named; under the limit split (board/bank_layout.h, docs/board.md "Ray split") the rays
  // are dealt so that the one result bank no longer caps the stream (under the paper's nominal split it did):
  // the lanes' grouping over the ray banks bounds it, below the three lanes' peak.
  EXPECT_NE(model23.note.find("(bound: "), std::string::npos) << model23.note;
  EXPECT_LT(model23.intersections_per_s, 3 * model23.clock_mhz * 1e6);
}

// Our estimate: lanes that fit with the wrapper counted, streaming at the pass-timing formula's
// long-pass rate, whose bound is named.
TEST(ThroughputEstimates, ModelEstimatesCountTheWrapperAndTheResultBank) {
  const double software_rate = 2e7;
  const std::vector<PaperEstimate> paper = paper_rule_estimates(software_rate);
  const std::vector<PaperEstimate> e = model_estimates(software_rate, 15);
  ASSERT_EQ(e.size(), paper.size());
  // The model's bandwidth limit: the same 2.4 GB/s over the bytes its two-lane design moves: at 15
  // bits three coordinate words per packet of two rays and the shared result word read and written,
  // (3 + 2) x 4 / 2 = 10 bytes per intersection, not the paper's 6.125.
  EXPECT_EQ(e[0].rule, EstimateRule::Model);
  EXPECT_NEAR(e[0].bytes_per_intersection, 10.0, 1e-3);
  EXPECT_DOUBLE_EQ(e[0].bytes_per_intersection, e[1].bytes_per_intersection);
  EXPECT_DOUBLE_EQ(e[0].intersections_per_s, 2.4e9 / e[0].bytes_per_intersection);
  for (const PaperEstimate& x : e) EXPECT_FALSE(x.clock_assumption.empty()) << x.estimate;
  for (const PaperEstimate& x : paper) EXPECT_FALSE(x.clock_assumption.empty()) << x.estimate;
  const pipeline::ResourceModel model = pipeline::ResourceModel::load_default();
  for (std::size_t i = 1; i < e.size(); ++i) {
    EXPECT_EQ(e[i].rule, EstimateRule::Model);
    EXPECT_EQ(e[i].device, paper[i].device);
    EXPECT_LE(e[i].intersections_per_s, e[i].lanes * e[i].clock_mhz * 1e6 * (1 + 1e-12)) << e[i].device;
    EXPECT_NEAR(e[i].gb_per_s, e[i].bytes_per_cycle * e[i].clock_mhz * 1e6 / 1e9, 1e-9);
    EXPECT_FALSE(why_estimates_differ(paper[i], e[i]).empty());
  }
  // The measured RC2000 design: two lanes at 52.5 MHz share result words, read and written in
  // 100 MHz banks: 2 ceil(R / 2) accesses take ceil(2 ceil(R / 2) x 10000 / 19048) device cycles.
  EXPECT_EQ(e[1].lanes, 2);
  EXPECT_NE(e[1].note.find("results"), std::string::npos);
  EXPECT_NEAR(e[1].intersections_per_s / (e[1].clock_mhz * 1e6), 1.905, 1e-3);
  for (std::size_t i = 2; i < e.size(); ++i) {
    const DeviceProfile d = find_device_profile(e[i].device);
    EXPECT_EQ(e[i].lanes, max_lanes(d, model, 15)) << e[i].device;
    EXPECT_FALSE(fit_design(d, model, e[i].lanes + 1, 15).fits) << e[i].device;
  }
}

}  // namespace
}  // namespace rc::board

// ---- Floating point (docs/pipeline.md, "Resources, clock and lanes that fit") ----------------

namespace rc::board {
namespace {

// Coordinates of 1+E+M bits packed as fixed-point coordinates are: floor(32 / width) per word.
TEST(ThroughputEstimates, FloatBytesPerIntersectionFollowTheWordWidth) {
  EXPECT_DOUBLE_EQ(bytes_per_intersection(pipeline::FloatFormat(8, 23)), 3 * 4 + 0.125);  // 32 bits: one per word
  EXPECT_DOUBLE_EQ(bytes_per_intersection(pipeline::FloatFormat(6, 13)), 3 * 4 + 0.125);  // 20 bits: one per word
  EXPECT_DOUBLE_EQ(bytes_per_intersection(pipeline::FloatFormat(5, 10)), 3 * 2 + 0.125);  // 16 bits: two per word
  EXPECT_DOUBLE_EQ(bytes_per_intersection(pipeline::FloatFormat(5, 7)), 3 * 2 + 0.125);   // 13 bits: two per word
  EXPECT_DOUBLE_EQ(bytes_per_intersection(pipeline::FloatFormat(2, 5)), 3 * 1 + 0.125);   // 8 bits: four per word
  EXPECT_DOUBLE_EQ(bytes_per_intersection(pipeline::FloatFormat(10, 24)), 3 * 8 + 0.125); // 35 bits: two words
}

// The table of docs/pipeline.md ("Resources, clock and lanes that fit"), printed by this test.
TEST(ThroughputEstimates, FixedAndFloatLanesAtFullRate) {
  const char* devices[] = {"xc2v6000", "virtex4-sx55", "spartan3-5000"};
  std::printf("| device | arithmetic | word bits | lanes (block + slice mults) | slices | block mults | clock MHz | "
              "intersections/s | bytes/intersection | GB/s needed | of RC2000's 2.4 GB/s |\n"
              "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const char* name : devices) {
    const DeviceProfile d = find_device_profile(name);
    std::vector<FullRateFit> rows;
    for (int bits : {15, 19, 23}) rows.push_back(fixed_full_rate_fit(d, bits));
    for (const auto& [e, m] : {std::pair{8, 23}, {6, 13}, {5, 10}, {5, 7}}) rows.push_back(float_full_rate_fit(d, pipeline::FloatFormat(e, m)));
    for (const FullRateFit& r : rows) {
      EXPECT_DOUBLE_EQ(r.intersections_per_s, r.lanes * r.clock_mhz * 1e6);
      EXPECT_DOUBLE_EQ(r.gb_per_s_needed, r.intersections_per_s * r.bytes_per_intersection / 1e9);
      EXPECT_DOUBLE_EQ(r.rc2000_gb_per_s, 2.4);
      const bool is_float = r.arithmetic.rfind("float:", 0) == 0;
      const int word = is_float ? pipeline::parse_float_format(r.arithmetic).bits_per_value() : std::stoi(r.arithmetic.substr(6));
      std::printf("| %s | %s | %d | %d (%d + %d) | %d | %d | %.1f | %.3g | %.3f | %.2f | %.0f%% |\n", r.device.c_str(),
                  r.arithmetic.c_str(), word, r.lanes, r.hard_lanes, r.soft_lanes, r.slices, r.block_multipliers, r.clock_mhz,
                  r.intersections_per_s, r.bytes_per_intersection, r.gb_per_s_needed,
                  100 * r.gb_per_s_needed / r.rc2000_gb_per_s);
    }
  }
}

}  // namespace
}  // namespace rc::board
