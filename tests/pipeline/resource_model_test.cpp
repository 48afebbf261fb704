// The resource and clock model reproduces every figure the paper measured and behaves sanely
// (monotone, flagged) where it interpolates.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "pipeline/fixed_format.h"
#include "pipeline/resource_model.h"

namespace rc::pipeline {
namespace {

const ResourceModel& model() {
  static const ResourceModel m = ResourceModel::load(std::string(RC_SOURCE_DIR) + "/configs/pipeline_resources.json");
  return m;
}

TEST(PipelineResources, DefaultPathIsTheConfigOfThisTree) {
  EXPECT_NO_THROW(ResourceModel::load_default());
  EXPECT_NE(ResourceModel::default_path().find("configs/pipeline_resources.json"), std::string::npos);
}

TEST(PipelineResources, ReproducesThePapersPipelineFigures) {
  struct Row { int bits; bool hard; int slices; double mhz; int mults; };
  for (const Row& r : {Row{7, false, 1951, 219.5, 0}, Row{15, false, 5471, 185.5, 0},
                       Row{23, false, 10615, 132.3, 0}, Row{31, false, 16889, 59.6, 0},
                       Row{7, true, 1128, 200.7, 27}, Row{15, true, 1976, 176.9, 30}}) {
    const PipelineResources p = model().pipeline(r.bits, r.hard);
    EXPECT_EQ(p.slices, r.slices) << r.bits;
    EXPECT_DOUBLE_EQ(p.clock_mhz, r.mhz) << r.bits;
    EXPECT_EQ(p.block_multipliers, r.mults) << r.bits;
    EXPECT_FALSE(p.interpolated || p.extrapolated) << r.bits;
  }
}

TEST(PipelineResources, BlockMultiplierCountFollowsOperandWidths) {
  // 18x18 pieces: every product fits one block up to 14 bits; at 15 the three sign products
  // (u, v, t are N+4 = 19 bits) need two each: Table 1's 27 and 30.
  EXPECT_EQ(ResourceModel::block_multipliers_needed(7), 27);
  EXPECT_EQ(ResourceModel::block_multipliers_needed(14), 27);
  EXPECT_EQ(ResourceModel::block_multipliers_needed(15), 30);
  EXPECT_EQ(ResourceModel::block_multipliers_needed(16), 30);
  EXPECT_EQ(ResourceModel::block_multipliers_needed(17), 42);  // pvec/qvec operand 19 bits
  EXPECT_EQ(ResourceModel::block_multipliers_needed(18), 102);
  EXPECT_EQ(ResourceModel::block_multipliers_needed(31), 102);
  EXPECT_EQ(ResourceModel::blocks_per_product(18, 18), 1);
  EXPECT_EQ(ResourceModel::blocks_per_product(19, 2), 2);
  EXPECT_EQ(ResourceModel::blocks_per_product(35, 35), 4);
  EXPECT_EQ(ResourceModel::blocks_per_product(36, 36), 9);
}

TEST(PipelineResources, InterpolatedWidthsAreFlaggedAndMonotone) {
  for (bool hard : {false, true}) {
    PipelineResources previous = model().pipeline(kMinFracBits, hard);
    for (int bits = kMinFracBits + 1; bits <= kMaxFracBits; ++bits) {
      const PipelineResources p = model().pipeline(bits, hard);
      EXPECT_GT(p.slices, previous.slices) << bits << (hard ? " hard" : " soft");
      EXPECT_LT(p.clock_mhz, previous.clock_mhz) << bits << (hard ? " hard" : " soft");
      EXPECT_GE(p.block_multipliers, previous.block_multipliers);
      const bool measured = hard ? (bits == 15) : (bits == 15 || bits == 23 || bits == 31);
      EXPECT_EQ(p.interpolated, !measured) << bits;
      EXPECT_EQ(p.extrapolated, hard && bits > 15) << bits;
      previous = p;
    }
  }
}

TEST(PipelineResources, BlockMultipliersAlwaysSaveSlicesAndCostClock) {
  for (int bits = kMinFracBits; bits <= kMaxFracBits; ++bits) {
    const PipelineResources soft = model().pipeline(bits, false), hard = model().pipeline(bits, true);
    EXPECT_LT(hard.slices, soft.slices) << bits;
    EXPECT_LT(hard.clock_mhz, soft.clock_mhz) << bits;
    EXPECT_EQ(soft.block_multipliers, 0);
  }
}

TEST(PipelineResources, QuadraticInterpolationJoinsTheMeasuredPointsSmoothly) {
  // Measured values are returned at measured widths and the fit in between; every one-bit step
  // must stay within 50% of the measured average slope of its interval (no jumps at the joins).
  const int measured[] = {7, 15, 23, 31};
  for (int i = 0; i + 1 < 4; ++i) {
    const int a = measured[i], b = measured[i + 1];
    const double slope = double(model().pipeline(b, false).slices - model().pipeline(a, false).slices) / (b - a);
    const double clock_slope = (model().pipeline(b, false).clock_mhz - model().pipeline(a, false).clock_mhz) / (b - a);
    for (int n = a; n < b; ++n) {
      const PipelineResources p = model().pipeline(n, false), q = model().pipeline(n + 1, false);
      EXPECT_NEAR((q.slices - p.slices) / slope, 1.0, 0.5) << n;
      EXPECT_NEAR((q.clock_mhz - p.clock_mhz) / clock_slope, 1.0, 0.5) << n;
    }
  }
}

TEST(PipelineResources, WrapperCostIsSolvedFromTheOneAndTwoLaneDesigns) {
  const WrapperCost w = model().wrapper();
  // 3339 = F + (1976 + w), 5562 = F + 2 (1976 + w)  =>  w = 247, F = 1116.
  EXPECT_EQ(w.per_lane_slices, 247);
  EXPECT_EQ(w.fixed_slices, 1116);
  EXPECT_EQ(w.block_multipliers, 0);
  const DesignResources one = model().design(15, true, 1), two = model().design(15, true, 2);
  EXPECT_EQ(one.slices, 3339);
  EXPECT_EQ(one.block_multipliers, 30);
  EXPECT_DOUBLE_EQ(one.clock_mhz, 53.833);
  EXPECT_FALSE(one.interpolated);
  EXPECT_EQ(two.slices, 5562);
  EXPECT_EQ(two.block_multipliers, 60);
  EXPECT_DOUBLE_EQ(two.clock_mhz, 52.5);
  EXPECT_FALSE(two.interpolated);
}

TEST(PipelineResources, DesignsScaleLinearlyInLanes) {
  for (int lanes = 1; lanes <= 8; ++lanes) {
    const DesignResources d = model().design(11, false, lanes);
    const PipelineResources p = model().pipeline(11, false);
    EXPECT_EQ(d.slices, 1116 + lanes * (p.slices + 247));
    EXPECT_EQ(d.block_multipliers, 0);
    EXPECT_TRUE(d.interpolated);
    EXPECT_LE(d.clock_mhz, p.clock_mhz);
  }
  EXPECT_DOUBLE_EQ(model().design(15, true, 6).clock_mhz, 52.5);  // held beyond 2 lanes
  EXPECT_TRUE(model().design(15, true, 3).interpolated);
  EXPECT_DOUBLE_EQ(model().design(31, false, 1).clock_mhz, 53.833);  // wrapper-limited
  EXPECT_THROW(model().design(15, true, 0), std::invalid_argument);
}

TEST(PipelineResources, RejectsBadWidthsAndBadFiles) {
  EXPECT_THROW(model().pipeline(6, false), std::invalid_argument);
  EXPECT_THROW(model().pipeline(32, true), std::invalid_argument);
  EXPECT_THROW(ResourceModel::load("/nonexistent/resources.json"), std::runtime_error);
  EXPECT_THROW(ResourceModel::from_text("{ not json"), std::runtime_error);
  try {
    ResourceModel::from_text(R"({"device": {"name": "x", "slices": 1, "block_multipliers": 1}})");
    FAIL() << "accepted a device without a source";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("source"), std::string::npos) << e.what();
  }
}

TEST(PipelineResources, ReferenceDeviceIsTheXc2v6000) {
  EXPECT_EQ(model().reference_device().name, "XC2V6000");
  EXPECT_EQ(model().reference_device().slices, 33792);
  EXPECT_EQ(model().reference_device().block_multipliers, 144);
}

}  // namespace
}  // namespace rc::pipeline

// ---- Floating point: estimates by the documented rules (docs/pipeline.md, "Resources, clock and
// lanes that fit"); the hand computations below follow resource_model.cpp's rules term by term.
namespace rc::pipeline {
namespace {

TEST(PipelineResourcesFloat, FamiliesFollowThePartPrefix) {
  EXPECT_EQ(model().float_family_of_part("XC2V6000").name, "Virtex-II");
  EXPECT_EQ(model().float_family_of_part("XC2V6000").block_multiplier, "MULT18X18");
  EXPECT_EQ(model().float_family_of_part("XC4VSX55").block_multiplier, "DSP48");
  EXPECT_EQ(model().float_family_of_part("xc3s5000").name, "Spartan-3");
  EXPECT_THROW(model().float_family_of_part("XC7K70T"), std::invalid_argument);
}

TEST(PipelineResourcesFloat, CalibrationsOnThePapersFixedLanes) {
  // Slice multipliers: (5471 - 1976) slices over sum(a*b) = 12*16*16 + 12*16*17 + 3*19*2 = 6450.
  EXPECT_DOUBLE_EQ(model().soft_multiplier_slices_per_bit_product(), (5471.0 - 1976.0) / 6450.0);
  // Counted fixed arithmetic: 266 LUTs at 7 bits, 483 at 15; glue = Table 1 minus ceil(LUTs/2):
  // 1128 - 133 = 995 and 1976 - 242 = 1734, linear in between and beyond.
  EXPECT_EQ(ResourceModel::fixed_arithmetic_luts(7), 266);
  EXPECT_EQ(ResourceModel::fixed_arithmetic_luts(15), 483);
  EXPECT_DOUBLE_EQ(model().glue_slices(7), 995);
  EXPECT_DOUBLE_EQ(model().glue_slices(15), 1734);
  EXPECT_DOUBLE_EQ(model().glue_slices(32), 995 + (1734.0 - 995) * 25 / 8);
}

TEST(PipelineResourcesFloat, OperatorsByTheCountingRules) {
  // float:8,23: p = 24, w = 27, L = 5. Adder 18 + 48 + 270 + 9 + 28 + 27 + 25 + 10 + 16 = 451 LUTs.
  const FloatOperatorCost a823 = model().float_adder(FloatFormat(8, 23));
  EXPECT_EQ(a823.luts, 451);
  EXPECT_EQ(a823.slices, 226);
  // Multiplier: 2*10 + 24 + 25 + 1 + 16 = 86, plus 3 adders of 48 bits for 4 blocks = 230 LUTs.
  const FloatOperatorCost m823 = model().float_multiplier(FloatFormat(8, 23), true);
  EXPECT_EQ(m823.luts, 230);
  EXPECT_EQ(m823.slices, 115);
  EXPECT_EQ(m823.block_multipliers, 4);
  // In slices: ceil(86 / 2) + ceil(0.5419 * 576) = 43 + 313.
  EXPECT_EQ(model().float_multiplier(FloatFormat(8, 23), false).slices, 356);
  // float:5,10: p = 11, w = 14, L = 4. Adder 12 + 22 + 112 + 5 + 15 + 14 + 12 + 7 + 10 = 209.
  EXPECT_EQ(model().float_adder(FloatFormat(5, 10)).slices, 105);
  const FloatOperatorCost m510 = model().float_multiplier(FloatFormat(5, 10), true);
  EXPECT_EQ(m510.luts, 48);
  EXPECT_EQ(m510.block_multipliers, 1);
  EXPECT_EQ(model().float_multiplier(FloatFormat(5, 10), false).slices, 24 + 66);
  // Block tiling ceil(p/17)^2.
  EXPECT_EQ(ResourceModel::float_multiplier_blocks(FloatFormat(5, 16)), 1);  // p = 17
  EXPECT_EQ(ResourceModel::float_multiplier_blocks(FloatFormat(5, 17)), 4);  // p = 18
  EXPECT_EQ(ResourceModel::float_multiplier_blocks(FloatFormat(8, 24)), 4);  // p = 25
}

TEST(PipelineResourcesFloat, LanesByHand) {
  for (const FloatFamily& family : model().float_families()) {
    // float:8,23: 24 x 115 + 21 x 226 + ceil(113 / 2) + round(3304.375) = 10867 slices, 96 blocks.
    const FloatPipelineResources s = model().float_pipeline(FloatFormat(8, 23), family, true);
    EXPECT_EQ(s.multipliers, 24);
    EXPECT_EQ(s.add_subs, 21);
    EXPECT_EQ(s.decision_slices, 57);
    EXPECT_EQ(s.glue_slices, 3304);
    EXPECT_EQ(s.slices, 10867) << family.name;
    EXPECT_EQ(s.block_multipliers, 96);
    EXPECT_EQ(s.clock_frac_bits, 24);
    EXPECT_DOUBLE_EQ(s.clock_mhz, model().pipeline(24, true).clock_mhz);
    EXPECT_TRUE(s.clock_extrapolated);
    EXPECT_EQ(model().float_pipeline(FloatFormat(8, 23), family, false).slices, 16651);
    // float:5,10: 24 x 24 + 21 x 105 + 31 + round(1826.375) = 4638 slices, 24 blocks, clock of 11 bits.
    const FloatPipelineResources h = model().float_pipeline(FloatFormat(5, 10), family, true);
    EXPECT_EQ(h.slices, 4638) << family.name;
    EXPECT_EQ(h.block_multipliers, 24);
    EXPECT_DOUBLE_EQ(h.clock_mhz, model().pipeline(11, true).clock_mhz);
    EXPECT_FALSE(h.clock_extrapolated);
    EXPECT_EQ(model().float_pipeline(FloatFormat(5, 10), family, false).slices, 6222);
  }
}

TEST(PipelineResourcesFloat, MonotoneInTheFraction) {
  const FloatFamily& family = model().float_family("Virtex-4");
  for (int e : {5, 8}) {
    for (bool hard : {true, false}) {
      FloatPipelineResources previous = model().float_pipeline(FloatFormat(e, 1), family, hard);
      for (int m = 2; m <= kMaxFractionBits; ++m) {
        const FloatPipelineResources r = model().float_pipeline(FloatFormat(e, m), family, hard);
        EXPECT_GT(r.slices, previous.slices) << e << "," << m;
        EXPECT_GE(r.block_multipliers, previous.block_multipliers);
        EXPECT_LE(r.clock_mhz, previous.clock_mhz) << e << "," << m;
        EXPECT_GT(r.adder.luts, previous.adder.luts);
        previous = r;
      }
    }
  }
}

}  // namespace
}  // namespace rc::pipeline
