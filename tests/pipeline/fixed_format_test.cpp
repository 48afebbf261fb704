// Widths, quantisation and face records: the pipeline's input format (paper sec 3.3).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "pipeline/fixed_mt.h"

namespace rc::pipeline {
namespace {

template <class F>
std::string thrown_message(F f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

TEST(PipelineFormat, AcceptsExactlyTheWidthsSevenToThirtyOne) {
  for (int bits = kMinFracBits; bits <= kMaxFracBits; ++bits) EXPECT_NO_THROW(validate_frac_bits(bits));
  for (int bits : {-1, 0, 6, 32, 64}) EXPECT_THROW(validate_frac_bits(bits), std::invalid_argument);
  const std::string message = thrown_message([] { validate_frac_bits(32); });
  EXPECT_NE(message.find("32"), std::string::npos) << message;
  EXPECT_NE(message.find("7 to 31"), std::string::npos) << message;
}

// FracBits is valid by construction: an int becomes one only through the check, and reads back as
// the same int.
TEST(PipelineFormat, FracBitsIsValidByConstruction) {
  for (int bits = kMinFracBits; bits <= kMaxFracBits; ++bits) {
    const FracBits b = bits;
    EXPECT_EQ(b.value(), bits);
    EXPECT_EQ(static_cast<int>(b), bits);
  }
  for (int bits : {-1, 0, 6, 32}) EXPECT_THROW(FracBits{bits}, std::invalid_argument);
  EXPECT_EQ(thrown_message([] { FracBits b = 40; (void)b; }), thrown_message([] { validate_frac_bits(40); }));
}

TEST(PipelineFormat, EveryEntryPointValidatesTheWidth) {
  const FaceRecord face{{1, 1, 1}, {2, 0, 0}, {0, 2, 0}};
  const FixedVec3 p{1, 1, 1};
  std::uint8_t blocked = 0;
  const std::int64_t x = 1;
  EXPECT_THROW(quantize_point({0.5, 0.5, 0.5}, 6), std::invalid_argument);
  EXPECT_THROW(make_face_record({}, 40), std::invalid_argument);
  EXPECT_THROW(segment_hits(face, p, p, 6), std::invalid_argument);
  EXPECT_THROW(trace(face, p, p, 32), std::invalid_argument);
  EXPECT_THROW(stage1(face, p, p, 0), std::invalid_argument);
  EXPECT_THROW(occlude_face(face, p, &x, &x, &x, 1, 99, &blocked), std::invalid_argument);
}

TEST(PipelineFormat, QuantisationIsFloorOfScaledValue) {
  EXPECT_EQ(quantize_coordinate(0.0, 7), 0);
  EXPECT_EQ(quantize_coordinate(0.5, 7), 64);
  EXPECT_EQ(quantize_coordinate(std::nextafter(0.5, 0.0), 7), 63);  // floor, not round
  EXPECT_EQ(quantize_coordinate(std::nextafter(1.0, 0.0), 31), (std::int64_t{1} << 31) - 1);
  EXPECT_EQ(quantize_coordinate(1.0 - std::ldexp(1.0, -31), 31), (std::int64_t{1} << 31) - 1);
  EXPECT_EQ(quantize_coordinate(1.0 - std::ldexp(1.0, -30), 31), (std::int64_t{1} << 31) - 2);
  EXPECT_EQ(quantize_coordinate(1.0 - std::ldexp(1.0, -31), 7), 127);
  const FixedVec3 q = quantize_point({0.25, 0.75, 0.125}, 15);
  EXPECT_EQ(q, (FixedVec3{1 << 13, 3 << 13, 1 << 12}));
}

TEST(PipelineFormat, QuantisationRejectsValuesOutsideTheUnitInterval) {
  for (double x : {-1e-300, -1.0, 1.0, 1.5, std::numeric_limits<double>::infinity(),
                   std::numeric_limits<double>::quiet_NaN()}) {
    EXPECT_THROW(quantize_coordinate(x, 15), std::out_of_range) << x;
  }
  const std::string message = thrown_message([] { quantize_point({0.5, 1.25, 0.5}, 15); });
  EXPECT_NE(message.find("1.25"), std::string::npos) << message;
}

TEST(PipelineFormat, FaceRecordHoldsVertexZeroAndExactEdges) {
  const Triangle t{{0.1, 0.2, 0.3}, {0.9, 0.05, 0.3}, {0.2, 0.8, 0.99}};
  for (int bits = kMinFracBits; bits <= kMaxFracBits; ++bits) {
    const FaceRecord f = make_face_record(t, bits);
    EXPECT_EQ(f.v0, quantize_point(t.v0, bits));
    EXPECT_EQ(f.edge1, quantize_point(t.v1, bits) - quantize_point(t.v0, bits));
    EXPECT_EQ(f.edge2, quantize_point(t.v2, bits) - quantize_point(t.v0, bits));
    EXPECT_TRUE(is_face_record(f, bits));
  }
}

TEST(PipelineFormat, RecognisesOutOfFormatInputs) {
  const int bits = 7;
  EXPECT_TRUE(is_position({0, 127, 64}, bits));
  EXPECT_FALSE(is_position({0, 128, 64}, bits));
  EXPECT_FALSE(is_position({-1, 0, 0}, bits));
  // Edges in range but v0 + edge1 outside [0, 2^N): not a difference of two positions.
  EXPECT_FALSE(is_face_record({{100, 0, 0}, {100, 0, 0}, {0, 0, 0}}, bits));
  EXPECT_TRUE(is_face_record({{100, 0, 0}, {-100, 0, 0}, {27, 127, 127}}, bits));
}

// A face smaller than the grid, or one whose corners round onto a line, has no area at that
// width, and then no segment can hit it: the case the run warns about.
TEST(PipelineFormat, AFaceWithoutAreaOnTheGridIsFound) {
  const Triangle unit{{0.1, 0.1, 0.5}, {0.6, 0.1, 0.5}, {0.1, 0.6, 0.5}};
  EXPECT_FALSE(has_no_area(make_face_record(unit, 7)));
  // 1e-3 across: three distinct points at 15 bits (2^-15 = 3.1e-5), one point at 7 bits (0.0078).
  const Triangle tiny{{0.5, 0.5, 0.5}, {0.501, 0.5, 0.5}, {0.5, 0.501, 0.5}};
  EXPECT_TRUE(has_no_area(make_face_record(tiny, 7)));
  EXPECT_FALSE(has_no_area(make_face_record(tiny, 15)));
  // A sliver whose third corner rounds onto the line of the other two.
  const Triangle sliver{{0.25, 0.25, 0.25}, {0.75, 0.25, 0.25}, {0.5, 0.25 + 1e-4, 0.25}};
  EXPECT_TRUE(has_no_area(make_face_record(sliver, 7)));
  EXPECT_FALSE(has_no_area(make_face_record(sliver, 31)));
  const FixedVec3 p{0, 0, 0}, q{100, 100, 100};
  EXPECT_EQ(segment_hits(make_face_record(tiny, 7), p, q, 7), 0);
  // The largest edges the format has: the cross product needs more than 64 bits.
  const std::int64_t big = (std::int64_t{1} << 31) - 1;
  EXPECT_FALSE(has_no_area(FaceRecord{{0, 0, 0}, {big, 0, 0}, {0, big, 0}}));
  EXPECT_TRUE(has_no_area(FaceRecord{{0, 0, 0}, {big, big, 0}, {-big, -big, 0}}));
}

}  // namespace
}  // namespace rc::pipeline
