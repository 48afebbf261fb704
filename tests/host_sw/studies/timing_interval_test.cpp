// The timing interval run prints (host_sw/studies/timing_interval.h): paper's prediction interval for
// one simulated time, from the shipped variants' left-out errors, and the calibration-range warnings.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "host_sw/studies/paper_prediction.h"
#include "host_sw/studies/timing_interval.h"

namespace rc {
namespace {

TEST(TimingInterval, IsPapersIntervalOfOneTime) {
  const std::vector<CalibratedVariant> variants = load_calibrated_variants(default_variants_path());
  const std::vector<PaperRow> rows = load_paper_table(default_paper_table_path());
  std::size_t count = 0;
  const auto [e_low, e_high] = left_out_error_quantiles(variants, &count);
  EXPECT_GT(count, 0u);
  const TimingInterval t = timing_interval(100, 70, 280, variants, rows);
  const auto expected = prediction_interval(100, 100, e_low, e_high);
  EXPECT_EQ(t.low_seconds, expected.first);
  EXPECT_EQ(t.high_seconds, expected.second);
  EXPECT_LT(t.low_seconds, 100);
  EXPECT_GT(t.high_seconds, 100);
  EXPECT_TRUE(t.warnings.empty());  // 70 faces, 280 patches: Table 2's smallest scene
}

TEST(TimingInterval, WarnsNamingTheQuantityOutsideTheCalibration) {
  const std::vector<CalibratedVariant> variants = load_calibrated_variants(default_variants_path());
  const std::vector<PaperRow> rows = load_paper_table(default_paper_table_path());
  const TimingInterval t = timing_interval(1, 100000, 280, variants, rows);
  ASSERT_EQ(t.warnings.size(), 1u);
  EXPECT_EQ(t.warnings[0].rfind("faces 100000 is outside the calibration's range 70..", 0), 0u) << t.warnings[0];
  const TimingInterval p = timing_interval(1, 70, 10, variants, rows);
  ASSERT_EQ(p.warnings.size(), 1u);
  EXPECT_EQ(p.warnings[0].rfind("patches 10 is outside the calibration's range 280..", 0), 0u) << p.warnings[0];
}

}  // namespace
}  // namespace rc
