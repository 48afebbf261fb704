// Arithmetic: "fixed" or float:E,M, parsed once; its name is the text, its format the float parser's.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "pipeline/arithmetic.h"

namespace rc::pipeline {
namespace {

TEST(Arithmetic, FixedIsTheDefaultAndHasNoFloatFormat) {
  const Arithmetic fixed;
  EXPECT_FALSE(fixed.is_float());
  EXPECT_EQ(fixed.name(), "fixed");
  EXPECT_TRUE(Arithmetic::parse("fixed") == fixed);
  EXPECT_THROW((void)fixed.float_format(), std::logic_error);
}

TEST(Arithmetic, AFloatFormatParsesOnceToItsFormat) {
  const Arithmetic single = Arithmetic::parse("float:8,23");
  ASSERT_TRUE(single.is_float());
  EXPECT_EQ(single.float_format().exponent_bits(), 8);
  EXPECT_EQ(single.float_format().fraction_bits(), 23);
  EXPECT_EQ(single.name(), "float:8,23");
  EXPECT_TRUE(single == Arithmetic(FloatFormat(8, 23)));
  EXPECT_TRUE(single != Arithmetic::parse("float:5,10"));
  EXPECT_EQ(Arithmetic(FloatFormat(5, 10)).name(), "float:5,10");
}

TEST(Arithmetic, AnythingElseIsRefusedWithTheFloatParsersMessage) {
  for (const std::string text : {"float", "Fixed", "float:8", "float:8,23x", ""}) {
    std::string arithmetic_error, format_error;
    try {
      (void)Arithmetic::parse(text);
    } catch (const std::invalid_argument& e) {
      arithmetic_error = e.what();
    }
    try {
      (void)parse_float_format(text);
    } catch (const std::invalid_argument& e) {
      format_error = e.what();
    }
    EXPECT_FALSE(arithmetic_error.empty()) << text;
    EXPECT_EQ(arithmetic_error, format_error) << text;
  }
}

}  // namespace
}  // namespace rc::pipeline
