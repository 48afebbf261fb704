// The overflow proof: documented register widths, and every intermediate of extreme inputs
// inside its proven range, at every width.
#include <gtest/gtest.h>

#include <random>

#include "pipeline/bit_bounds.h"
#include "pipeline/fixed_mt.h"

namespace rc::pipeline {
namespace {

TEST(PipelineBounds, RegisterWidthsAreTheDocumentedOnes) {
  for (int n = kMinFracBits; n <= kMaxFracBits; ++n) {
    SCOPED_TRACE(n);
    EXPECT_EQ(signed_bits(Quantity::Position, n), n + 1);  // unsigned 0.N
    EXPECT_EQ(signed_bits(Quantity::Difference, n), n + 1);
    EXPECT_EQ(signed_bits(Quantity::Product1Raw, n), 2 * n + 1);
    EXPECT_EQ(signed_bits(Quantity::Product1, n), n + 1);
    EXPECT_EQ(signed_bits(Quantity::CrossComponent, n), n + 2);
    EXPECT_EQ(signed_bits(Quantity::Product2Raw, n), 2 * n + 2);
    EXPECT_EQ(signed_bits(Quantity::Product2, n), n + 2);
    EXPECT_EQ(signed_bits(Quantity::DotPartial, n), n + 3);
    EXPECT_EQ(signed_bits(Quantity::Dot, n), n + 4);
    EXPECT_EQ(signed_bits(Quantity::SignedDot, n), n + 4);
    EXPECT_EQ(signed_bits(Quantity::AbsDet, n), n + 4);
    EXPECT_EQ(signed_bits(Quantity::UvSum, n), n + 5);
    EXPECT_TRUE(core_fits<std::int64_t>(n));
    EXPECT_EQ(core_fits<std::int32_t>(n), n <= 15);
  }
}

TEST(PipelineBounds, ClosedFormsOfTheRanges) {
  for (int n = kMinFracBits; n <= kMaxFracBits; ++n) {
    const std::int64_t one = std::int64_t{1} << n;
    EXPECT_EQ(value_range(Quantity::Product1, n).lo, -(one - 1));
    EXPECT_EQ(value_range(Quantity::Product1, n).hi, one - 2);
    EXPECT_EQ(value_range(Quantity::CrossComponent, n).hi, 2 * one - 3);
    EXPECT_EQ(value_range(Quantity::Product2, n).lo, -(2 * one - 4));
    EXPECT_EQ(value_range(Quantity::Product2, n).hi, 2 * one - 5);
    EXPECT_EQ(value_range(Quantity::Dot, n).lo, -(6 * one - 12));
    EXPECT_EQ(value_range(Quantity::Dot, n).hi, 6 * one - 15);
  }
}

void expect_within_bounds(const FaceRecord& face, const FixedVec3& start, const FixedVec3& end, int bits) {
  const Trace t = trace(face, start, end, bits);
  for (int m = 0; m < kMultiplierCount; ++m) {
    ASSERT_TRUE(value_range(result_of(static_cast<Multiplier>(m)), bits).contains(t.multipliers[m]))
        << name(static_cast<Multiplier>(m)) << " = " << t.multipliers[m] << " at " << bits << " bits";
  }
  for (int a = 0; a < kAddSubCount; ++a) {
    ASSERT_TRUE(value_range(result_of(static_cast<AddSub>(a)), bits).contains(t.add_subs[a]))
        << name(static_cast<AddSub>(a)) << " = " << t.add_subs[a] << " at " << bits << " bits";
  }
  ASSERT_TRUE(value_range(Quantity::AbsDet, bits).contains(t.values.stage3.abs_det));
  // Same answer from the 128-bit instantiation: no 64-bit product overflowed.
  const auto w = [](const FixedVec3& v) { return vec_cast<__int128>(v); };
  NoProbe probe;
  const auto wide = run_pipeline(w(face.v0), w(face.edge1), w(face.edge2), w(start), w(end), bits, probe);
  ASSERT_TRUE(wide.stage2.det == t.values.stage2.det && wide.stage3.u == t.values.stage3.u &&
              wide.stage3.v == t.values.stage3.v && wide.stage3.t == t.values.stage3.t &&
              wide.stage3.hit == t.hit());
}

// Every triangle and segment with corners of the cube [0, 2^N - 1]^3 as points: these maximise
// the magnitudes of edges, directions and cross products.
TEST(PipelineBounds, CubeCornerInputsStayInRangeAtEveryWidth) {
  for (int bits = kMinFracBits; bits <= kMaxFracBits; ++bits) {
    const std::int64_t m = (std::int64_t{1} << bits) - 1;
    FixedVec3 corner[8];
    for (int i = 0; i < 8; ++i) corner[i] = {(i & 1) ? m : 0, (i & 2) ? m : 0, (i & 4) ? m : 0};
    for (int a = 0; a < 8; ++a)
      for (int b = 0; b < 8; ++b)
        for (int c = 0; c < 8; ++c) {
          const FaceRecord face{corner[a], corner[b] - corner[a], corner[c] - corner[a]};
          for (int s = 0; s < 8; ++s)
            for (int e = 0; e < 8; ++e) expect_within_bounds(face, corner[s], corner[e], bits);
        }
  }
}

TEST(PipelineBounds, NearExtremeRandomInputsStayInRange) {
  std::mt19937_64 rng(7);
  for (int bits = kMinFracBits; bits <= kMaxFracBits; ++bits) {
    const std::int64_t m = (std::int64_t{1} << bits) - 1;
    const std::int64_t values[6] = {0, 1, 2, m - 2, m - 1, m};
    const auto point = [&] {
      return FixedVec3{values[rng() % 6], values[rng() % 6], values[rng() % 6]};
    };
    for (int i = 0; i < 4000; ++i) {
      const FixedVec3 v0 = point(), v1 = point(), v2 = point();
      expect_within_bounds({v0, v1 - v0, v2 - v0}, point(), point(), bits);
    }
  }
}

}  // namespace
}  // namespace rc::pipeline
