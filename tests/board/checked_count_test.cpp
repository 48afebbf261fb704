// CheckedCount (board/checked_count.h): a count outside Min..Max never exists; the error names the
// quantity, the number and both bounds. LaneCount's bound is the CONFIG register's 8-bit lane field.
#include "board/checked_count.h"

#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>

#include <gtest/gtest.h>

#include "board/lane_count.h"

namespace rc::board {
namespace {

struct WidgetTag {
  static constexpr std::string_view what = "widget count";
  static constexpr std::string_view why = "a test's widgets";
};
using WidgetCount = CheckedCount<WidgetTag, 3, 7>;

std::string message_of(long long n) {
  try {
    WidgetCount w = n;
    (void)w;
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(CheckedCount, HoldsEveryNumberWithinItsBounds) {
  for (int n = 3; n <= 7; ++n) EXPECT_EQ(WidgetCount(n).value(), static_cast<unsigned>(n));
  EXPECT_EQ(static_cast<unsigned>(WidgetCount(std::uint8_t{7})), 7u);
  EXPECT_EQ(WidgetCount(std::size_t{3}).value(), 3u);
  static_assert(WidgetCount::kMin == 3 && WidgetCount::kMax == 7);
}

TEST(CheckedCount, RefusesEveryNumberOutsideNamingQuantityAndBounds) {
  for (long long bad : {2LL, 8LL, 0LL, -1LL, -3LL, 1LL << 32, (1LL << 32) + 3, std::numeric_limits<long long>::min()}) {
    EXPECT_EQ(message_of(bad), "widget count " + std::to_string(bad) + " is out of range: at least 3 and at most 7 (a test's widgets)");
  }
  // Unsigned values that wrap to a small number when narrowed are refused, not truncated.
  EXPECT_THROW(WidgetCount{std::numeric_limits<std::uint64_t>::max()}, std::invalid_argument);
  EXPECT_THROW(WidgetCount{std::uint64_t{1} << 32 | 5}, std::invalid_argument);
}

TEST(CheckedCount, AssignmentChecksAndKeepsTheOldValueOnRefusal) {
  WidgetCount w = 4;
  EXPECT_THROW(w = 9, std::invalid_argument);
  EXPECT_EQ(w.value(), 4u);
  w = 6;
  EXPECT_EQ(w.value(), 6u);
}

// The lane bound is the hardware's: CONFIG's lane field [7:0] holds 8 bits, so 255 lanes at most.
TEST(CheckedCount, LaneCountIsBoundByTheConfigRegister) {
  static_assert(LaneCount::kMin == 1);
  static_assert(LaneCount::kMax == (1u << 8) - 1);
  EXPECT_EQ(LaneCount(255).value(), 255u);
  EXPECT_THROW(LaneCount{256}, std::invalid_argument);
  EXPECT_THROW(LaneCount{0}, std::invalid_argument);
  static_assert(!std::is_convertible_v<bool, LaneCount>, "a flag is not a count");
}

}  // namespace
}  // namespace rc::board
