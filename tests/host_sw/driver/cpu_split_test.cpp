// The CPU/FPGA split's arithmetic (host_sw/driver/cpu_split.h): shares, rounding, the balance, and
// the option text.
#include <gtest/gtest.h>

#include <stdexcept>

#include "host_sw/driver/cpu_split.h"

namespace rc {
namespace {

TEST(CpuSplitArithmetic, FixedShareRoundsToTheNearestSegment) {
  EXPECT_EQ(fixed_cpu_segments(10, 0.0), 0u);
  EXPECT_EQ(fixed_cpu_segments(10, 1.0), 10u);
  EXPECT_EQ(fixed_cpu_segments(10, 0.25), 3u);  // 2.5: halves up
  EXPECT_EQ(fixed_cpu_segments(10, 0.24), 2u);
  EXPECT_EQ(fixed_cpu_segments(0, 0.5), 0u);
  EXPECT_EQ(fixed_cpu_segments(3, 0.999999), 3u);
}

// k x cpu = (n - k) x board: k = n board / (board + cpu).
TEST(CpuSplitArithmetic, BalancedEvensBothSides) {
  EXPECT_EQ(balanced_cpu_segments(100, 1.0, 1.0), 50u);
  EXPECT_EQ(balanced_cpu_segments(100, 3.0, 1.0), 25u);  // 25 x 3 = 75 x 1
  EXPECT_EQ(balanced_cpu_segments(100, 1.0, 4.0), 80u);  // 80 x 1 = 20 x 4
  EXPECT_EQ(balanced_cpu_segments(100, 1.0, 0.0), 0u);   // nothing measured yet: the board
  EXPECT_EQ(balanced_cpu_segments(7, 0.0, 1.0), 7u);     // free tests: all on the CPU
}

TEST(CpuSplitArithmetic, OptionTextAndItsLimits) {
  const CpuSplit a = parse_cpu_split("0.25", 2);
  EXPECT_EQ(a.mode, CpuSplit::Mode::fixed);
  EXPECT_EQ(a.share, 0.25);
  EXPECT_EQ(a.name(), "0.25 on 2 cpus");
  EXPECT_EQ(parse_cpu_split("balanced", 1).name(), "balanced on 1 cpu");
  EXPECT_EQ(CpuSplit{}.name(), "off");
  for (const char* bad : {"1.5", "-0.1", "half", "", "nan", "0.5x"}) {
    try {
      (void)parse_cpu_split(bad, 1);
      FAIL() << bad << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("--cpu-share"), std::string::npos) << e.what();
    }
  }
  try {
    (void)parse_cpu_split("0.5", 3);
    FAIL() << "3 cores accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("--cpu-cores"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace rc
