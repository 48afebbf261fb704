// pipeline::HitRegion never excludes an end point the pipeline reports as a hit: on the numerical
// stress cases (random, crossing, exact edge and vertex hits, grazing, parallel, degenerate,
// end-on-triangle, extreme coordinates, near-coplanar) at every width, in exact integer
// arithmetic, in double and in the float box test.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "tests/host_sw/visibility/fast_test_support.h"
#include "pipeline/fixed_mt.h"
#include "pipeline/hit_region.h"
#include "pipeline/stress_cases.h"

namespace rc::pipeline {
namespace {

struct QuantisedCase {
  FaceRecord face;
  FixedVec3 start, end;
};

QuantisedCase quantise(const StressCase& c, int bits) {
  return {make_face_record(c.triangle, bits), quantize_point(c.start, bits), quantize_point(c.end, bits)};
}

// A box around p, `below` and `above` LSB wider on each axis, as floats rounded outwards.
constexpr int kBoxes = HitRegion::kBoxes;
constexpr unsigned kAllBoxes = (1u << kBoxes) - 1;

void box_around(const FixedVec3& p, std::int64_t below, std::int64_t above, int bits, int lane,
                float lanes[2][3][kBoxes]) {
  const std::int64_t max = std::int64_t{1} << bits;
  const std::int64_t c[3] = {p.x, p.y, p.z};
  for (int a = 0; a < 3; ++a) {
    const double lo = static_cast<double>(std::max<std::int64_t>(0, c[a] - below));
    const double hi = static_cast<double>(std::min<std::int64_t>(max, c[a] + above));
    float l = static_cast<float>(lo), h = static_cast<float>(hi);
    if (static_cast<double>(l) > lo) l = std::nextafter(l, -std::numeric_limits<float>::infinity());
    if (static_cast<double>(h) < hi) h = std::nextafter(h, std::numeric_limits<float>::infinity());
    lanes[0][a][lane] = l;
    lanes[1][a][lane] = h;
  }
}

// For every stress case and its reversed segment: a pipeline hit lies in the exact conditions,
// the double region and every float box around it.
TEST(HitRegion, NeverExcludesAPipelineHitAtAnyWidth) {
  test::Rng rng(3);
  for (int bits = kMinFracBits; bits <= kMaxFracBits; ++bits) {
    std::size_t hits = 0;
    for (int k = 0; k < kCaseKindCount; ++k) {
      const CaseKind kind = static_cast<CaseKind>(k);
      for (const StressCase& sc : make_stress_cases(kind, bits, 4000, 1000 * bits + k)) {
        QuantisedCase c = quantise(sc, bits);
        for (int reversed = 0; reversed < 2; ++reversed, std::swap(c.start, c.end)) {
          if (!segment_hits(c.face, c.start, c.end, bits)) continue;
          ++hits;
          const ExactHitConditions exact = exact_hit_conditions(c.face, c.start, bits);
          const HitRegion region(c.face, c.start, bits);
          ASSERT_FALSE(exact.empty) << name(kind) << " at " << bits << " bits";
          ASSERT_FALSE(region.empty());
          ASSERT_TRUE(exact.allows(c.end - c.start)) << name(kind) << " at " << bits << " bits";
          ASSERT_TRUE(region.may_hit(double(c.end.x), double(c.end.y), double(c.end.z)))
              << name(kind) << " at " << bits << " bits";
          float lanes[2][3][kBoxes] = {};
          for (int lane = 0; lane < kBoxes; ++lane) {
            const std::int64_t reach = lane == 0 ? 0 : rng.integer(0, std::int64_t{1} << (bits - 3));
            // One draw per statement (argument order is unspecified; this is the order gcc used).
            const std::int64_t above = rng.integer(0, reach), below = rng.integer(0, reach);
            box_around(c.end, below, above, bits, lane, lanes);
          }
          ASSERT_EQ(region.may_hit_boxes(lanes), kAllBoxes) << name(kind) << " at " << bits << " bits";
        }
      }
    }
    EXPECT_GT(hits, 500u) << bits << " bits: too few hits to test anything";
  }
}

// The four error bounds the conditions rest on (docs/fast-visibility.md), checked directly on the
// pipeline's own det, u and v: with M = 2^N, d = end - start, n_det = edge2 x edge1,
// n_u = edge2 x tvec, W = n_det - n_u - M qvec (qvec the pipeline's), each residual
//   M^2 det - d.n_det,  M^2 u - d.n_u,  M v - d.qvec,  M^2 (det - u - v) - d.W
// lies in the interval derived there. Also records how much of each interval is used.
TEST(HitRegion, TruncationErrorsStayInsideTheDerivedBounds) {
  using Wide = __int128;
  const auto cross = [](const FixedVec3& a, const FixedVec3& b) {
    return IntVec3<Wide>{Wide(a.y) * b.z - Wide(a.z) * b.y, Wide(a.z) * b.x - Wide(a.x) * b.z,
                         Wide(a.x) * b.y - Wide(a.y) * b.x};
  };
  const auto dot = [](const FixedVec3& d, const IntVec3<Wide>& n) { return d.x * n.x + d.y * n.y + d.z * n.z; };
  const auto l1 = [](const FixedVec3& v) { return Wide(std::llabs(v.x) + std::llabs(v.y) + std::llabs(v.z)); };
  double worst[4][2] = {};  // per quantity: the largest share of the lower and upper bound used
  for (int bits : {7, 8, 11, 15, 16, 23, 30, 31}) {
    const Wide m = Wide{1} << bits, m1 = m - 1;
    for (int k = 0; k < kCaseKindCount; ++k) {
      for (const StressCase& sc : make_stress_cases(static_cast<CaseKind>(k), bits, 1500, 31 * bits + k)) {
        const QuantisedCase c = quantise(sc, bits);
        const Trace tr = trace(c.face, c.start, c.end, bits);
        const FixedVec3 d = c.end - c.start, tvec = tr.values.stage1.tvec, q = tr.values.stage2.qvec;
        const Wide det = tr.values.stage2.det, u = tr.values.stage3.u, v = tr.values.stage3.v;
        const IntVec3<Wide> n_det = cross(c.face.edge2, c.face.edge1), n_u = cross(c.face.edge2, tvec);
        const IntVec3<Wide> w{n_det.x - n_u.x - m * q.x, n_det.y - n_u.y - m * q.y, n_det.z - n_u.z - m * q.z};
        const Wide e1 = m1 * l1(c.face.edge1), et = m1 * l1(tvec), three = 3 * m1 * m;
        const Wide residual[4] = {m * m * det - dot(d, n_det), m * m * u - dot(d, n_u),
                                  m * v - (d.x * Wide(q.x) + d.y * Wide(q.y) + d.z * Wide(q.z)),
                                  m * m * (det - u - v) - dot(d, w)};
        const Wide lo[4] = {-e1 - three, -et - three, -3 * m1, -e1 - et - three};
        const Wide hi[4] = {e1, et, 0, e1 + et + 2 * three};
        for (int i = 0; i < 4; ++i) {
          ASSERT_GE(residual[i], lo[i]) << "quantity " << i << ", " << name(static_cast<CaseKind>(k)) << ", " << bits;
          ASSERT_LE(residual[i], hi[i]) << "quantity " << i << ", " << name(static_cast<CaseKind>(k)) << ", " << bits;
          if (lo[i] < 0) worst[i][0] = std::max(worst[i][0], double(residual[i]) / double(lo[i]));
          if (hi[i] > 0) worst[i][1] = std::max(worst[i][1], double(residual[i]) / double(hi[i]));
        }
      }
    }
  }
  for (int i = 0; i < 4; ++i) {
    std::printf("quantity %d (det, u, v, det-u-v): up to %.3f of the lower bound, %.3f of the upper\n", i,
                worst[i][0], worst[i][1]);
    EXPECT_GT(worst[i][0], 0.5) << "the lower bound of quantity " << i << " is far from tight";
  }
}

// Why the culling is algebraic rather than geometric: a segment lying (almost) in a face's plane
// has exact det, u, v and t near 0 wherever it lies, and truncation can turn that into a hit on a
// face the segment passes nowhere near. No widening of the face's bounding box by a few LSB
// would keep such a hit; the hit region does.
TEST(HitRegion, KeepsPhantomHitsFarFromTheFace) {
  for (int bits : {15, 31}) {
    double farthest = 0;
    for (const StressCase& sc : make_stress_cases(CaseKind::Parallel, bits, 20000, 5)) {
      const QuantisedCase c = quantise(sc, bits);
      if (!segment_hits(c.face, c.start, c.end, bits)) continue;
      // Distance from the segment to the triangle's bounding box, sampled along the segment.
      const Triangle& t = sc.triangle;
      const Vec3 lo = glm::min(t.v0, glm::min(t.v1, t.v2)), hi = glm::max(t.v0, glm::max(t.v1, t.v2));
      double nearest = 1e9;
      for (int i = 0; i <= 1000; ++i) {
        const Vec3 p = sc.start + (sc.end - sc.start) * (i / 1000.0);
        nearest = std::min(nearest, glm::length(p - glm::clamp(p, lo, hi)));
      }
      farthest = std::max(farthest, nearest);
      const HitRegion region(c.face, c.start, bits);
      ASSERT_TRUE(region.may_hit(double(c.end.x), double(c.end.y), double(c.end.z)));
    }
    std::printf("%d bits: a phantom hit %.3f (scene units) from the face's bounding box\n", bits, farthest);
    EXPECT_GT(farthest, 0.05) << bits << " bits";
  }
}

// t == 0 (the start on the face's plane in the pipeline's arithmetic) is the one case where no
// end point can hit, and both forms say so.
TEST(HitRegion, EmptyExactlyWhenTIsZero) {
  for (int bits : {7, 15, 31}) {
    std::size_t empties = 0;
    for (const StressCase& sc : make_stress_cases(CaseKind::Parallel, bits, 2000, 5)) {
      const QuantisedCase c = quantise(sc, bits);
      const FixedVec3 none{0, 0, 0};
      const Stage1Result s1 = stage1(c.face, c.start, none, bits);
      const std::int64_t t = stage3(c.face, none, s1, stage2(c.face, s1, bits), bits).t;
      const HitRegion region(c.face, c.start, bits);
      EXPECT_EQ(region.empty(), t == 0);
      EXPECT_EQ(exact_hit_conditions(c.face, c.start, bits).empty, t == 0);
      if (t == 0) {
        ++empties;
        EXPECT_FALSE(region.may_hit(double(c.end.x), double(c.end.y), double(c.end.z)));
        float box[2][3][kBoxes] = {};
        for (int a = 0; a < 3; ++a)
          for (int j = 0; j < kBoxes; ++j) box[1][a][j] = static_cast<float>(std::int64_t{1} << bits);
        EXPECT_EQ(region.may_hit_boxes(box), 0u);
      }
    }
    EXPECT_GT(empties, 10u) << bits;
  }
}

// The double test keeps everything the exact conditions allow, and drops almost everything they
// exclude (its margin is 2^-44 of the scale): it is a faithful version, not a loose one.
TEST(HitRegion, DoubleTestAgreesWithExactConditions) {
  test::Rng rng(8);
  for (int bits : {7, 11, 15, 23, 31}) {
    std::size_t allowed = 0, excluded = 0, loose = 0;
    for (const StressCase& sc : make_stress_cases(CaseKind::Crossing, bits, 300, 77 + bits)) {
      const QuantisedCase c = quantise(sc, bits);
      const ExactHitConditions exact = exact_hit_conditions(c.face, c.start, bits);
      const HitRegion region(c.face, c.start, bits);
      if (exact.empty) continue;
      for (int i = 0; i < 40; ++i) {
        // End points scattered around the case's end point at all scales.
        const std::int64_t r = std::int64_t{1} << rng.integer(0, bits - 1);
        const std::int64_t max = (std::int64_t{1} << bits) - 1;
        const auto near = [&](std::int64_t v) { return std::clamp<std::int64_t>(v + rng.integer(-r, r), 0, max); };
        const FixedVec3 e{near(c.end.x), near(c.end.y), near(c.end.z)};
        const bool in_exact = exact.allows(e - c.start);
        const bool in_double = region.may_hit(double(e.x), double(e.y), double(e.z));
        if (in_exact) {
          ++allowed;
          ASSERT_TRUE(in_double) << bits << " bits";
        } else {
          ++excluded;
          loose += in_double;
        }
      }
    }
    EXPECT_GT(allowed, 100u) << bits;
    EXPECT_LE(loose, excluded / 1000) << bits << " bits: the double margin is far too wide";
  }
}

// The culling is worth having: at the paper's width most end points of random segments that
// miss are excluded.
TEST(HitRegion, ExcludesMostMisses) {
  const int bits = 15;
  std::size_t misses = 0, kept = 0;
  for (const StressCase& sc : make_stress_cases(CaseKind::Random, bits, 5000, 4)) {
    const QuantisedCase c = quantise(sc, bits);
    if (segment_hits(c.face, c.start, c.end, bits)) continue;
    ++misses;
    kept += HitRegion(c.face, c.start, bits).may_hit(double(c.end.x), double(c.end.y), double(c.end.z));
  }
  EXPECT_LT(kept, misses / 20);
}

TEST(HitRegion, RejectsBadWidths) {
  const FaceRecord face{{1, 1, 1}, {2, 0, 0}, {0, 2, 0}};
  EXPECT_THROW(HitRegion(face, {0, 0, 0}, 6), std::invalid_argument);
  EXPECT_THROW(exact_hit_conditions(face, {0, 0, 0}, 32), std::invalid_argument);
}

}  // namespace
}  // namespace rc::pipeline
