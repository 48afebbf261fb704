#include <gtest/gtest.h>

#include "board/design_fit.h"
#include "board/throughput_estimates.h"

namespace rc::board {
namespace {

// Sec 5.6(a)'s accounting: three coordinate fields read and one result bit written.
TEST(ThroughputEstimates, BytesPerIntersectionFollowTheWordFormat) {
  EXPECT_DOUBLE_EQ(bytes_per_intersection(15), 3 * 2 + 0.125);  // two 16-bit fields per 32-bit word
  EXPECT_DOUBLE_EQ(bytes_per_intersection(7), 3 * 1 + 0.125);   // four 8-bit fields
  EXPECT_DOUBLE_EQ(bytes_per_intersection(23), 3 * 4 + 0.125);  // one field per word
}

TEST(ThroughputEstimates, BandwidthLimitAndLaneRatesAreTheirFormulas) {
  const double software_rate = 2e7;
  const std::vector<PaperEstimate> e = paper_estimates(software_rate, 15);
  ASSERT_GE(e.size(), 5u);
  // RC2000: 6 banks x 4 bytes x 100 MHz = 2.4 GB/s, over 6.125 bytes per intersection.
  EXPECT_EQ(e[0].estimate, "RC2000 bandwidth limit");
  EXPECT_NEAR(e[0].gb_per_s, 2.4, 1e-12);
  EXPECT_NEAR(e[0].intersections_per_s, 2.4e9 / 6.125, 1e-3);
  EXPECT_NEAR(e[0].speedup_vs_software, 2.4e9 / 6.125 / software_rate, 1e-9);
  // Two lanes at the measured two-lane clock.
  EXPECT_NEAR(e[1].intersections_per_s, 2 * 52.5e6, 1e-3);
  EXPECT_NEAR(e[1].bytes_per_cycle, 2 * 6.125, 1e-12);
  // Lanes that fit: lanes x clock, and the lane count is the largest that fits.
  const pipeline::ResourceModel model = pipeline::ResourceModel::load_default();
  for (std::size_t i = 2; i < e.size(); ++i) {
    const DeviceProfile d = find_device_profile(e[i].device);
    EXPECT_EQ(e[i].lanes, max_lanes(d, model, 15)) << e[i].device;
    EXPECT_FALSE(fit_design(d, model, e[i].lanes + 1, 15).fits) << e[i].device;
    EXPECT_NEAR(e[i].intersections_per_s, e[i].lanes * e[i].clock_mhz * 1e6, 1e-3);
    EXPECT_NEAR(e[i].gb_per_s, e[i].bytes_per_cycle * e[i].clock_mhz * 1e6 / 1e9, 1e-9);
  }
}

}  // namespace
}  // namespace rc::board
