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
  EXPECT_THROW(ResourceModel::from_json_text("{ not json"), std::runtime_error);
  try {
    ResourceModel::from_json_text(R"({"device": {"name": "x", "slices": 1, "block_multipliers": 1}})");
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
