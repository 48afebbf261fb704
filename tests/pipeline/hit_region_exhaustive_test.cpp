// The hit region's component-wise error bounds (zero factors lose nothing to their floors) are
// tightest on axis-aligned faces at narrow widths, where truncation makes phantom hits far from
// the face. At 7 bits every end point of the 128^3 grid can be tried: for each face and start
// below, every end point the pipeline reports as a hit must lie inside the region (exact 128-bit
// conditions and the double test).
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "pipeline/fixed_mt.h"
#include "pipeline/hit_region.h"

namespace rc::pipeline {
namespace {

// Faces in the planes x, y or z = const, half with short edges (a few LSB, as the Cornell Box's
// faces are at 7 bits: they can hit only through truncation) and half with long ones (real hits
// need |det| > |t|, which at 7 bits takes edges of tens of LSB), a third with edges of many
// trailing zeros, and starts anywhere.
std::vector<std::pair<FaceRecord, FixedVec3>> axis_aligned_cases(int count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const auto coordinate = [&] { return static_cast<std::int64_t>(rng() % 128); };
  std::vector<std::pair<FaceRecord, FixedVec3>> out;
  while (static_cast<int>(out.size()) < count) {
    const int axis = static_cast<int>(rng() % 3);
    const std::int64_t span = 1 + static_cast<std::int64_t>(rng() % (out.size() % 2 ? 8 : 127));
    FixedVec3 v0{coordinate(), coordinate(), coordinate()};
    const auto offset = [&] { return static_cast<std::int64_t>(rng() % (2 * span + 1)) - span; };
    FixedVec3 e1{offset(), offset(), offset()}, e2{offset(), offset(), offset()};
    if (out.size() % 3 == 0) e1 = {span & ~1, 0, -(span & ~3)}, e2 = {0, 4, span & ~1};  // many trailing zeros
    (axis == 0 ? e1.x : axis == 1 ? e1.y : e1.z) = 0;
    (axis == 0 ? e2.x : axis == 1 ? e2.y : e2.z) = 0;
    const FaceRecord face{v0, e1, e2};
    if (!is_face_record(face, 7)) continue;
    out.push_back({face, {coordinate(), coordinate(), coordinate()}});
  }
  return out;
}

TEST(HitRegionExhaustive, EveryPipelineHitOnTheSevenBitGridIsInsideTheRegion) {
  const int bits = 7, n = 128;
  std::vector<std::int64_t> x, y, z;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      for (int k = 0; k < n; ++k) x.push_back(i), y.push_back(j), z.push_back(k);
    }
  }
  std::size_t hits = 0, allowed = 0;
  for (const auto& [face, start] : axis_aligned_cases(24, 7)) {
    std::vector<std::uint8_t> hit(x.size(), 0);
    occlude_face(face, start, x.data(), y.data(), z.data(), x.size(), bits, hit.data());
    const ExactHitConditions exact = exact_hit_conditions(face, start, bits);
    const HitRegion region(face, start, bits);
    for (std::size_t i = 0; i < x.size(); ++i) {
      const bool inside = region.may_hit(double(x[i]), double(y[i]), double(z[i]));
      allowed += inside;
      if (!hit[i]) continue;
      ++hits;
      const FixedVec3 d{x[i] - start.x, y[i] - start.y, z[i] - start.z};
      ASSERT_TRUE(exact.allows(d)) << "exact conditions drop a hit at " << x[i] << " " << y[i] << " " << z[i];
      ASSERT_TRUE(inside) << "double region drops a hit at " << x[i] << " " << y[i] << " " << z[i];
    }
  }
  EXPECT_GT(hits, 100u);           // phantom and real hits both occur at 7 bits
  EXPECT_LT(allowed, 24 * x.size() / 2);  // and the region still excludes most of the grid
}

}  // namespace
}  // namespace rc::pipeline
