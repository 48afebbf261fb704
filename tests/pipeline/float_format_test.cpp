// FloatFormat and round_to_format: the widths it accepts, the text it parses, and the rounding
// rules of docs/pipeline.md ("Floating-point pipeline") on hand-computed values.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

#include "pipeline/float_format.h"

namespace rc::pipeline {
namespace {

const FloatFormat kHalf(5, 10);
const FloatFormat kSingle(8, 23);

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

std::string message_of(int e, int m) {
  try {
    FloatFormat(e, m);
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "";
}

TEST(FloatFormat, DescribesItsLayout) {
  EXPECT_EQ(kHalf.bits_per_value(), 16);
  EXPECT_EQ(kSingle.bits_per_value(), 32);
  EXPECT_EQ(FloatFormat(6, 9).bits_per_value(), 16);
  EXPECT_EQ(kHalf.precision(), 11);
  EXPECT_EQ(kHalf.bias(), 15);
  EXPECT_EQ(kHalf.min_normal(), 0x1p-14);
  EXPECT_EQ(kHalf.max_finite(), 65504.0);
  EXPECT_EQ(kSingle.min_normal(), 0x1p-126);
  EXPECT_EQ(kSingle.max_finite(), 0x1.fffffep127);
  EXPECT_EQ(FloatFormat(2, 1).max_finite(), 3.0);   // exponents 0 and 1 only
  EXPECT_EQ(FloatFormat(2, 1).min_normal(), 1.0);
  EXPECT_EQ(kSingle.to_string(), "float:8,23");
  EXPECT_EQ(FloatFormat(6, 9), FloatFormat(6, 9));
  EXPECT_NE(FloatFormat(6, 9), FloatFormat(6, 10));
}

TEST(FloatFormat, RejectsWidthsOutsideTheSupportedRangeNamingTheLimit) {
  EXPECT_NE(message_of(1, 10).find("exponent bits 1 is out of range"), std::string::npos);
  EXPECT_NE(message_of(11, 10).find("2 to 10 exponent bits"), std::string::npos);
  EXPECT_NE(message_of(8, 0).find("fraction bits 0 is out of range"), std::string::npos);
  EXPECT_NE(message_of(8, 25).find("1 to 24 fraction bits"), std::string::npos);
  EXPECT_NE(message_of(11, 52).find("exponent bits 11"), std::string::npos);  // double itself
  EXPECT_EQ(message_of(2, 1), "");
  EXPECT_EQ(message_of(10, 24), "");
}

TEST(FloatFormat, ParsesFloatEM) {
  EXPECT_EQ(parse_float_format("float:8,23"), kSingle);
  EXPECT_EQ(parse_float_format("float:5,10"), kHalf);
  EXPECT_EQ(parse_float_format("float:6,9"), FloatFormat(6, 9));
  for (const char* bad : {"float", "float:", "float:8", "float:8,", "float:,23", "float:8,23,1",
                          "float:a,b", "float: 8,23", "float:8 ,23", "fixed:8,23", "Float:8,23",
                          "float:-8,23", "float:8,+23", "float:99999999999,1", "float:8;23"}) {
    try {
      parse_float_format(bad);
      ADD_FAILURE() << bad << " parsed";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("expected float:E,M"), std::string::npos) << bad;
    }
  }
  // Well-formed but out of range: the constructor's message.
  EXPECT_THROW(parse_float_format("float:12,10"), std::invalid_argument);
  EXPECT_THROW(parse_float_format("float:8,30"), std::invalid_argument);
  EXPECT_TRUE(names_float_format("float:8,23"));
  EXPECT_TRUE(names_float_format("float:junk"));
  EXPECT_FALSE(names_float_format("float"));
  EXPECT_FALSE(names_float_format("fixed"));
}

TEST(FloatFormat, ExactValuesAreUnchanged) {
  for (double x : {0.0, 1.0, -1.0, 0.5, 0.75, 1.0 + 0x1p-10, 65504.0, 0x1p-14, -0x1.ffcp-14, 3.0 / 4096}) {
    EXPECT_TRUE(same_bits(round_to_format(x, kHalf), x)) << x;
    EXPECT_TRUE(is_in_format(x, kHalf)) << x;
  }
  EXPECT_TRUE(same_bits(round_to_format(-0.0, kHalf), -0.0));
  EXPECT_FALSE(is_in_format(0.1, kHalf));
  EXPECT_FALSE(is_in_format(0x1p-15, kHalf));  // a half subnormal: not a value of the format
}

TEST(FloatFormat, RoundsToNearestTiesToEven) {
  // Half: the ulp of [1, 2) is 2^-10.
  EXPECT_EQ(round_to_format(1.0 + 0x1p-11, kHalf), 1.0);                       // tie, 1 is even
  EXPECT_EQ(round_to_format(1.0 + 3 * 0x1p-11, kHalf), 1.0 + 0x1p-9);          // tie, up to even
  EXPECT_EQ(round_to_format(1.0 + 0x1p-11 + 0x1p-40, kHalf), 1.0 + 0x1p-10);   // above the tie
  EXPECT_EQ(round_to_format(1.0 + 0x1p-11 - 0x1p-40, kHalf), 1.0);             // below the tie
  EXPECT_EQ(round_to_format(-(1.0 + 3 * 0x1p-11), kHalf), -(1.0 + 0x1p-9));    // symmetric
  EXPECT_EQ(round_to_format(2.0 - 0x1p-12, kHalf), 2.0);                       // carry into the exponent
  EXPECT_EQ(round_to_format(0.1, kHalf), 0x1.998p-4);
}

TEST(FloatFormat, FlushesTinyResultsToZeroAfterRounding) {
  EXPECT_TRUE(same_bits(round_to_format(0x1p-15, kHalf), 0.0));
  EXPECT_TRUE(same_bits(round_to_format(-0x1p-15, kHalf), -0.0));  // sign kept
  EXPECT_TRUE(same_bits(round_to_format(0x1.ffcp-15, kHalf), 0.0));  // representable with unbounded exponent
  // Half an ulp (of the binade below) under the smallest normal: ties to the even neighbour,
  // which is the smallest normal itself, so it is not tiny after rounding.
  EXPECT_EQ(round_to_format(0x1.ffep-15, kHalf), 0x1p-14);
  EXPECT_EQ(round_to_format(0x1p-14 - 0x1p-40, kHalf), 0x1p-14);
  EXPECT_TRUE(same_bits(round_to_format(5e-324, kSingle), 0.0));  // double subnormals too
  EXPECT_TRUE(same_bits(round_to_format(0x1p-127, kSingle), 0.0));
}

TEST(FloatFormat, OverflowsToInfinity) {
  EXPECT_EQ(round_to_format(65519.0, kHalf), 65504.0);
  EXPECT_EQ(round_to_format(65520.0, kHalf), INFINITY);   // the tie rounds to 2^16: overflow
  EXPECT_EQ(round_to_format(-1e6, kHalf), -INFINITY);
  EXPECT_EQ(round_to_format(0x1.fffffefp127, kSingle), 0x1.fffffep127);
  EXPECT_EQ(round_to_format(0x1.ffffffp127, kSingle), INFINITY);
  EXPECT_EQ(round_to_format(INFINITY, kHalf), INFINITY);
  EXPECT_TRUE(std::isnan(round_to_format(NAN, kHalf)));
}

// Single precision is the hardware's float: a double-to-float conversion rounds to nearest even
// and overflows to infinity, so it must agree wherever the float result is above the subnormal
// range.
TEST(FloatFormat, SingleAgreesWithTheHardwareConversion) {
  std::mt19937_64 rng(7);
  int compared = 0;
  for (int i = 0; i < 200000; ++i) {
    const std::uint64_t bits = rng();
    double x;
    std::memcpy(&x, &bits, sizeof x);
    int exponent = 0;
    x = std::ldexp(std::frexp(x, &exponent), static_cast<int>(rng() % 280) - 140);  // |x| near float's range
    if (std::isnan(x)) continue;
    const float f = static_cast<float>(x);
    if (std::fabs(f) <= 0x1p-126f) {
      // Gradual underflow (the hardware's) and flush to zero differ here by design.
      const double r = std::fabs(round_to_format(x, kSingle));
      EXPECT_TRUE(r == 0.0 || r == 0x1p-126) << x;
      continue;
    }
    ++compared;
    ASSERT_TRUE(same_bits(round_to_format(x, kSingle), static_cast<double>(f))) << x;
  }
  EXPECT_GT(compared, 150000);
}

}  // namespace
}  // namespace rc::pipeline
