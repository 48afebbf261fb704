#include <gtest/gtest.h>

#include "board/design_fit.h"

#include <algorithm>

namespace rc::board {
namespace {

// The paper's own designs: the XC2V6000 with one and two 15-bit block-multiplier pipelines
// (sec 5.4: 3339 slices, 30 multipliers, 53.833 MHz; sec 5.5: 5562 slices, 60, 52.5 MHz).
TEST(DesignFit, ReproducesThePapersMeasuredDesigns) {
  const DeviceProfile v2 = find_device_profile("xc2v6000");
  const pipeline::ResourceModel model = pipeline::ResourceModel::load_default();
  const DesignFit one = fit_design(v2, model, 1, 15);
  EXPECT_TRUE(one.fits);
  EXPECT_EQ(one.hard_lanes, 1);
  EXPECT_EQ(one.slices, 3339);
  EXPECT_EQ(one.block_multipliers, 30);
  EXPECT_DOUBLE_EQ(one.clock_mhz, 53.833);
  const DesignFit two = fit_design(v2, model, 2, 15);
  EXPECT_EQ(two.slices, 5562);
  EXPECT_EQ(two.block_multipliers, 60);
  EXPECT_DOUBLE_EQ(two.clock_mhz, 52.5);
  EXPECT_FALSE(two.modelled);
}

// Resource arithmetic on a synthetic device: the lanes that fit follow from slices and
// multipliers exactly as documented (block-multiplier lanes first, the rest in slices).
TEST(DesignFit, LanesThatFitFollowFromSlicesAndMultipliers) {
  const pipeline::ResourceModel model = pipeline::ResourceModel::load_default();
  const pipeline::WrapperCost w = model.wrapper();
  const pipeline::PipelineResources hard = model.pipeline(15, true), soft = model.pipeline(15, false);
  DeviceProfile d = find_device_profile("xc2v6000");
  d.name = "synthetic";
  d.block_multipliers = 2 * hard.block_multipliers + 5;  // room for two hard lanes only
  d.slices = w.fixed_slices + 3 * w.per_lane_slices + 2 * hard.slices + soft.slices;  // exactly 3 lanes
  EXPECT_EQ(max_lanes(d, model, 15), 3);
  const DesignFit three = fit_design(d, model, 3, 15);
  EXPECT_EQ(three.hard_lanes, 2);
  EXPECT_EQ(three.soft_lanes, 1);
  EXPECT_EQ(three.slices, d.slices);
  EXPECT_DOUBLE_EQ(three.pipeline_clock_mhz, std::min(hard.clock_mhz, soft.clock_mhz));
  d.slices -= 1;
  EXPECT_EQ(max_lanes(d, model, 15), 2);
  d.block_multipliers = 0;  // no multipliers at all: every lane in slices
  EXPECT_EQ(fit_design(d, model, 1, 15).soft_lanes, 1);
  EXPECT_THROW(fit_design(d, model, 0, 15), std::invalid_argument);
  EXPECT_THROW(fit_design(d, model, 1, 40), std::invalid_argument);
}

// A slower pipeline than the wrapper sets the clock: on a device whose profile clock is the
// 15-bit pipeline's, a wider pipeline slows the design down.
TEST(DesignFit, ClockIsTheSlowerOfDesignAndPipeline) {
  const pipeline::ResourceModel model = pipeline::ResourceModel::load_default();
  const DeviceProfile v4 = find_device_profile("virtex4-sx55");
  const DesignFit f15 = fit_design(v4, model, 1, 15);
  const DesignFit f31 = fit_design(v4, model, 1, 31);
  EXPECT_DOUBLE_EQ(f15.clock_mhz, 176.9);
  EXPECT_LT(f31.clock_mhz, f15.clock_mhz);
  EXPECT_DOUBLE_EQ(f31.clock_mhz, f31.pipeline_clock_mhz);
}

// LaneCount is valid by construction: 1..255 (the CONFIG register's 8 bits), from any integer type.
TEST(LaneCount, IsValidByConstruction) {
  EXPECT_EQ(LaneCount(1).value(), 1u);
  EXPECT_EQ(LaneCount(255u).value(), 255u);
  EXPECT_EQ(static_cast<unsigned>(LaneCount(std::size_t{8})), 8u);
  for (long bad : {0L, -1L, 256L, 1L << 40}) EXPECT_THROW(LaneCount{bad}, std::invalid_argument) << bad;
  try {
    LaneCount l = 0;
    (void)l;
    ADD_FAILURE() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("lane count 0 is out of range: at least 1 and at most 255"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace rc::board

// Floating-point lanes (estimates): hand-computed lane counts on the three devices, from the lane
// costs of PipelineResourcesFloat.LanesByHand and the wrapper (1116 + 247 per lane).
namespace rc::board {
namespace {

TEST(DesignFit, FloatLanesThatFitByHand) {
  const pipeline::ResourceModel model = pipeline::ResourceModel::load_default();
  struct Row { const char* device; int e, m, lanes, hard, slices, mults; };
  for (const Row& r : {Row{"xc2v6000", 8, 23, 2, 1, 1116 + 2 * 247 + 10867 + 16651, 96},
                       Row{"virtex4-sx55", 8, 23, 2, 2, 1116 + 2 * 247 + 2 * 10867, 192},
                       Row{"spartan3-5000", 8, 23, 2, 1, 1116 + 2 * 247 + 10867 + 16651, 96},
                       Row{"xc2v6000", 5, 10, 6, 6, 1116 + 6 * 247 + 6 * 4638, 144},
                       Row{"virtex4-sx55", 5, 10, 4, 4, 1116 + 4 * 247 + 4 * 4638, 96},
                       Row{"spartan3-5000", 5, 10, 5, 4, 1116 + 5 * 247 + 4 * 4638 + 6222, 96}}) {
    const DeviceProfile d = find_device_profile(r.device);
    const pipeline::FloatFormat f(r.e, r.m);
    EXPECT_EQ(max_float_lanes(d, model, f), r.lanes) << r.device << " " << f.to_string();
    const FloatDesignFit fit = fit_float_design(d, model, r.lanes, f);
    EXPECT_TRUE(fit.fits);
    EXPECT_TRUE(fit.modelled);
    EXPECT_EQ(fit.hard_lanes, r.hard) << r.device;
    EXPECT_EQ(fit.slices, r.slices) << r.device;
    EXPECT_EQ(fit.block_multipliers, r.mults) << r.device;
    EXPECT_EQ(fit.bits, 1 + r.e + r.m);
    EXPECT_FALSE(fit_float_design(d, model, r.lanes + 1, f).fits) << r.device;
    // The clock: the profile's (52.5 MHz wrapper on the XC2V6000, 176.9 MHz assumed elsewhere) or the
    // float lane's (the fixed lane's at N = p: 24 bits for float:8,23), whichever is slower.
    const double lane_clock = model.pipeline(r.m + 1, true).clock_mhz;
    const double soft_clock = model.pipeline(r.m + 1, false).clock_mhz;
    const double pipeline_clock = fit.soft_lanes > 0 ? std::min(lane_clock, soft_clock) : lane_clock;
    EXPECT_DOUBLE_EQ(fit.clock_mhz, std::min(d.clock_mhz(r.lanes), pipeline_clock)) << r.device;
  }
  EXPECT_EQ(fit_float_design(find_device_profile("virtex4-sx55"), model, 1, pipeline::FloatFormat(5, 10)).block_multiplier, "DSP48");
}

// Lanes that fit under each source, against the fit's arithmetic done by hand from the device
// profile: wrapper F + L (w + P) slices and L * blocks block multipliers, block lanes first.
TEST(DesignFit, LanesThatFitOnTheSec56DevicesUnderBothSourcesOfResources) {
  for (const char* name : {"xc2v6000", "virtex4-sx55", "spartan3-5000"}) {
    const DeviceProfile device = find_device_profile(name);
    const LanesBySource l = lanes_by_source(device, 15);
    for (pipeline::ResourceSource source : {pipeline::ResourceSource::paper_fit, pipeline::ResourceSource::synthesis}) {
      const pipeline::ResourceModel m = pipeline::ResourceModel::load_default(source);
      const pipeline::PipelineResources hard = m.pipeline(15, true, device.part), soft = m.pipeline(15, false, device.part);
      const pipeline::WrapperCost w = m.wrapper();
      int most = 0;
      for (int lanes = 1; lanes <= 255; ++lanes) {
        const int block_lanes = std::min(lanes, (device.block_multipliers - w.block_multipliers) / hard.block_multipliers);
        const int slices = w.fixed_slices + lanes * w.per_lane_slices + block_lanes * hard.slices + (lanes - block_lanes) * soft.slices;
        if (slices > device.slices) break;
        most = lanes;
      }
      const int got = source == pipeline::ResourceSource::synthesis ? l.synthesis_lanes : l.paper_lanes;
      EXPECT_EQ(got, most) << name << " " << choice_name(source);
      EXPECT_EQ((source == pipeline::ResourceSource::synthesis ? l.synthesis : l.paper).resources, source);
    }
  }
}

}  // namespace
}  // namespace rc::board
