// The guard band on the pipeline's t test (mt_core.h, core::decide(s, t_guard)): a hand-computed case
// where one LSB of guard turns a hit into a miss; the definition (g < t*s < |det| - g, u and v as
// before) against the stage values at every width; the vectorised kernels (every instruction-set
// variant, both integer paths, 32-bit banks, masked or not) against the scalar test with the guard; the
// culled backend's hit regions still enclosing every guarded hit; and the refusals.
#include <gtest/gtest.h>

#include <random>
#include <stdexcept>
#include <vector>

#include "pipeline/fixed_mt.h"
#include "pipeline/hit_region.h"
#include "pipeline/kernel_isa.h"

namespace rc::pipeline {
namespace {

// At 7 bits: the face z = 10 (v0 (0,0,10), edge1 (100,0,0), edge2 (0,100,0)), the segment from
// (20,20,9) to (20,20,109), crossing the plane one LSB after its start. By hand (products floor(a*b/128)):
//   pvec = dir x edge2 = (0 - floor(100*100/128), 0, 0) = (-78, 0, 0); det = floor(100*-78/128) = -61, s = -1
//   tvec = (20, 20, -1); qvec = tvec x edge1 = (0, floor(-100/128), -floor(2000/128)) = (0, -1, -15)
//   u = floor(20*-78/128) = -13, v = floor(100*-15/128) = -12, t = floor(100*-1/128) = -1
//   u*s = 13, v*s = 12, t*s = 1, |det| = 61: 0 < 13 < 61, 0 < 12, 25 < 61, 0 < 1 < 61, a hit;
//   with g = 1: 1 < t*s = 1 is false, a miss.
TEST(TGuard, OneLsbOfGuardTurnsAHandComputedHitAtTheStartIntoAMiss) {
  const FaceRecord face{{0, 0, 10}, {100, 0, 0}, {0, 100, 0}};
  const FixedVec3 start{20, 20, 9}, end{20, 20, 109};
  const Trace t = trace(face, start, end, 7);
  EXPECT_EQ(t.values.stage2.det, -61);
  EXPECT_EQ(t.values.stage3.u_signed, 13);
  EXPECT_EQ(t.values.stage3.v_signed, 12);
  EXPECT_EQ(t.values.stage3.t_signed, 1);
  EXPECT_EQ(t.values.stage3.abs_det, 61);
  EXPECT_TRUE(segment_hits(face, start, end, 7));
  EXPECT_TRUE(segment_hits(face, start, end, 7, 0));
  EXPECT_FALSE(segment_hits(face, start, end, 7, 1));
  EXPECT_FALSE(trace(face, start, end, 7, 1).hit());
  // The other end: reversed, t*s is |det| - 1 (the crossing one LSB before the end), the upper bound decides.
  const Trace back = trace(face, end, start, 7);
  ASSERT_TRUE(back.hit());
  const std::int64_t gap = back.values.stage3.abs_det - back.values.stage3.t_signed;
  ASSERT_GE(gap, 1);
  EXPECT_TRUE(segment_hits(face, end, start, 7, static_cast<int>(gap) - 1));
  EXPECT_FALSE(segment_hits(face, end, start, 7, static_cast<int>(gap)));
}

struct RandomCase {
  FaceRecord face;
  FixedVec3 start, end;
};

// Faces of every size and segments through them (about half hit), on the grid of `bits`.
std::vector<RandomCase> random_cases(int bits, std::size_t count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const std::int64_t top = (std::int64_t(1) << bits) - 1;
  std::uniform_int_distribution<std::int64_t> any(0, top);
  std::uniform_int_distribution<int> shift(0, bits - 3);
  std::vector<RandomCase> cases;
  for (std::size_t i = 0; i < count; ++i) {
    const std::int64_t size = std::max<std::int64_t>(4, top >> shift(rng));  // small faces too: |det| of a few LSBs
    std::uniform_int_distribution<std::int64_t> near(-size, size);
    const auto clamp = [top](std::int64_t v) { return std::min(top, std::max<std::int64_t>(0, v)); };
    const FixedVec3 c{any(rng), any(rng), any(rng)};
    const auto around = [&](const FixedVec3& p) { return FixedVec3{clamp(p.x + near(rng)), clamp(p.y + near(rng)), clamp(p.z + near(rng))}; };
    const FixedVec3 v0 = around(c), v1 = around(c), v2 = around(c);
    const FixedVec3 mid{(v0.x + v1.x + v2.x) / 3, (v0.y + v1.y + v2.y) / 3, (v0.z + v1.z + v2.z) / 3};
    const FixedVec3 start = i % 2 ? FixedVec3{any(rng), any(rng), any(rng)} : around(mid);
    const FixedVec3 through = mid - start;
    const FixedVec3 end{clamp(mid.x + through.x / 2 + near(rng) / 4), clamp(mid.y + through.y / 2 + near(rng) / 4),
                        clamp(mid.z + through.z / 2 + near(rng) / 4)};
    cases.push_back({{v0, v1 - v0, v2 - v0}, start, end});
  }
  return cases;
}

TEST(TGuard, TheScalarTestIsTheDefinitionAtEveryWidth) {
  std::size_t flipped = 0;
  for (int bits = kMinFracBits; bits <= kMaxFracBits; ++bits) {
    for (const RandomCase& c : random_cases(bits, 3000, 100 + bits)) {
      const Stage3Result& s = trace(c.face, c.start, c.end, bits).values.stage3;
      const bool unguarded = s.hit;
      EXPECT_EQ(segment_hits(c.face, c.start, c.end, bits, 0), unguarded);
      for (int g : {1, 2, 4, 255}) {
        const bool expected = 0 < s.u_signed && s.u_signed < s.abs_det && 0 < s.v_signed && s.uv_sum < s.abs_det &&
                              g < s.t_signed && s.t_signed < s.abs_det - g;
        const bool guarded = segment_hits(c.face, c.start, c.end, bits, g);
        ASSERT_EQ(guarded, expected) << bits << " bits, g " << g;
        ASSERT_TRUE(!guarded || unguarded) << "a guard only removes hits";
        EXPECT_EQ(trace(c.face, c.start, c.end, bits, g).hit(), guarded);
        flipped += guarded != unguarded;
      }
    }
  }
  EXPECT_GT(flipped, 100u);  // the cases reach the band
}

TEST(TGuard, EveryKernelVariantMatchesTheScalarTestWithTheGuard) {
  std::size_t hits = 0, flipped = 0;
  for (KernelIsa isa : supported_kernel_isas()) {
    for (int bits = kMinFracBits; bits <= kMaxFracBits; ++bits) {
      const std::vector<RandomCase> cases = random_cases(bits, 48, 900 + bits);
      for (int g : {1, 2, 4}) {
        for (const RandomCase& c : cases) {
          // One face and start against many ends: the case's own end and 63 around it.
          std::mt19937_64 rng(static_cast<std::uint64_t>(bits * 7 + g));
          const std::int64_t top = (std::int64_t(1) << bits) - 1;
          std::uniform_int_distribution<std::int64_t> jitter(-3, 3);
          std::vector<std::int64_t> x, y, z;
          std::vector<std::int32_t> x32, y32, z32;
          std::vector<std::uint8_t> skip;
          for (int k = 0; k < 64; ++k) {
            const auto j = [&](std::int64_t v) { return std::min(top, std::max<std::int64_t>(0, v + (k ? jitter(rng) : 0))); };
            x.push_back(j(c.end.x)), y.push_back(j(c.end.y)), z.push_back(j(c.end.z));
            x32.push_back(static_cast<std::int32_t>(x.back())), y32.push_back(static_cast<std::int32_t>(y.back()));
            z32.push_back(static_cast<std::int32_t>(z.back()));
            skip.push_back(k % 7 == 3);
          }
          for (bool masked : {false, true}) {
            std::vector<std::uint8_t> got(64, 0), got_dispatch(64, 0), got32(64, 0);
            const std::uint8_t* sk = masked ? skip.data() : nullptr;
            occlude_kernel(isa, bits, masked)(c.face, c.start, x.data(), y.data(), z.data(), 64, bits, got.data(), sk, g);
            occlude_face(isa, c.face, c.start, x.data(), y.data(), z.data(), 64, bits, got_dispatch.data(), sk, g);
            if (bits <= 15)
              occlude_kernel32(isa, bits, masked)(c.face, c.start, x32.data(), y32.data(), z32.data(), 64, bits, got32.data(), sk, g);
            for (int k = 0; k < 64; ++k) {
              const FixedVec3 e{x[k], y[k], z[k]};
              const bool expected = !(masked && skip[k]) && segment_hits(c.face, c.start, e, bits, g);
              ASSERT_EQ(got[k], expected) << name(isa) << ", " << bits << " bits, g " << g << ", end " << k;
              ASSERT_EQ(got_dispatch[k], expected) << name(isa) << ", " << bits << " bits, g " << g;
              if (bits <= 15) {
                ASSERT_EQ(got32[k], expected) << name(isa) << " (32-bit banks), " << bits << " bits, g " << g;
              }
              hits += expected;
              flipped += !expected && !(masked && skip[k]) && segment_hits(c.face, c.start, e, bits);
            }
          }
        }
      }
    }
  }
  EXPECT_GT(hits, 1000u);
  EXPECT_GT(flipped, 100u);
}

// The culled backend's hit regions are derived for 0 < t*s < |det|; a guarded hit satisfies it too.
TEST(TGuard, HitRegionsStillEncloseEveryGuardedHit) {
  std::size_t guarded_hits = 0;
  for (int bits : {7, 11, 15, 19, 23, 27, 31}) {
    for (const RandomCase& c : random_cases(bits, 3000, 500 + bits)) {
      if (!segment_hits(c.face, c.start, c.end, bits, 1)) continue;
      ++guarded_hits;
      const HitRegion region(c.face, c.start, bits);
      ASSERT_FALSE(region.empty());
      ASSERT_TRUE(region.may_hit(double(c.end.x), double(c.end.y), double(c.end.z))) << bits << " bits";
    }
  }
  EXPECT_GT(guarded_hits, 1000u);
}

TEST(TGuard, GuardsOutsideTheRegisterRangeAreRefused) {
  EXPECT_NO_THROW(validate_t_guard(0));
  EXPECT_NO_THROW(validate_t_guard(kMaxTGuard));
  EXPECT_EQ(kMaxTGuard, 255);
  for (int g : {-1, kMaxTGuard + 1}) {
    try {
      validate_t_guard(g);
      ADD_FAILURE() << g << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("0 to 255"), std::string::npos) << e.what();
    }
  }
  const FaceRecord face{{0, 0, 10}, {100, 0, 0}, {0, 100, 0}};
  std::vector<std::int64_t> x{20}, y{20}, z{109};
  std::vector<std::uint8_t> b(1, 0);
  EXPECT_THROW(occlude_face(face, {20, 20, 9}, x.data(), y.data(), z.data(), 1, 7, b.data(), nullptr, 256), std::invalid_argument);
  EXPECT_THROW(segment_hits(face, {20, 20, 9}, {20, 20, 109}, 7, -1), std::invalid_argument);
}

}  // namespace
}  // namespace rc::pipeline
