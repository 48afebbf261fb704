// The host-side segment fixes (host_sw/radiosity/segment_fixes.h): the offset moves ends exactly as
// documented, the neighbour rule gives "OR over the faces outside the own sheets and neighbours" of
// the pipeline's test, bit for bit, around the brute-force backend and the culled one, at every width
// 7..31, and a whole solve with SolverOptions::fixes is the same on both.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "host_sw/radiosity/radiosity.h"
#include "host_sw/radiosity/segment_fixes.h"
#include "host_sw/visibility/fast_visibility.h"
#include "host_sw/visibility/fixed_visibility.h"
#include "pipeline/fixed_mt.h"
#include "pipeline/reference_mt.h"
#include "tests/common/small_torus_scene.h"

namespace rc::test {
namespace {

TEST(SegmentFixes, VertexNeighboursShareAVertexAndRingTwoAddsTheirs) {
  // A strip of four triangles: 0-1, 1-2, 2-3 share edges; 0 and 2 share vertex b.
  const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0}, d{1, 1, 0}, e{2, 0, 0}, f{2, 1, 0}, g{3, 1, 0};
  const std::vector<Triangle> faces = {{a, b, c}, {b, d, c}, {b, e, d}, {e, f, d}, {f, g, e}};
  const auto one = vertex_neighbours(faces, 1);
  EXPECT_EQ(one[0], (std::vector<int>{1, 2}));
  EXPECT_EQ(one[4], (std::vector<int>{2, 3}));
  const auto two = vertex_neighbours(faces, 2);
  EXPECT_EQ(two[0], (std::vector<int>{1, 2, 3, 4}));
}

TEST(SegmentFixes, OffsetMovesKLsbsAlongTheNormalAndClamps) {
  const std::vector<Triangle> faces = {{{0.1, 0.5, 0.1}, {0.9, 0.5, 0.1}, {0.1, 0.5, 0.9}}};  // normal -y
  SegmentFixer fixer(faces, FaceSheets{}, {10, 3, 0});
  const Vec3 p = fixer.moved({0.3, 0.5, 0.3}, 0);
  EXPECT_EQ(p.y, 0.5 - 3.0 / 1024);
  EXPECT_EQ(p.x, 0.3);
  EXPECT_EQ(fixer.moved({0.3, 0.001, 0.3}, 0).y, 0.0);  // clamped into the grid
  EXPECT_EQ(fixer.moved({0.3, 0.5, 0.3}, -1), (Vec3{0.3, 0.5, 0.3}));  // no face: not moved
  EXPECT_THROW(SegmentFixer(faces, FaceSheets{}, {0, 1, 0}), std::invalid_argument);  // an offset needs a width
  EXPECT_THROW(SegmentFixer(faces, FaceSheets{}, {15, 0, 3}), std::invalid_argument);
  EXPECT_THROW(SegmentFixer(faces, FaceSheets{}, {15, 0, 0, 15}), std::invalid_argument);  // coordinates below the width
  EXPECT_THROW(SegmentFixer(faces, FaceSheets{}, {0, 0, 0, 11}), std::invalid_argument);
}

TEST(SegmentFixes, CoordinateBitsRoundFacesAndEndsToTheNarrowGrid) {
  const std::vector<Triangle> faces = {{{0.1, 0.5, 0.1}, {0.9, 0.5, 0.1}, {0.1, 0.5, 0.9}}};
  SegmentFixer fixer(faces, FaceSheets{}, {23, 0, 0, 11});
  EXPECT_EQ(fixer.faces()[0].v0.x, std::floor(0.1 * 2048) / 2048);
  EXPECT_EQ(fixer.moved({0.3, 0.7, 0.3}, 0).y, std::floor(0.7 * 2048) / 2048);
  SegmentFixer offset(faces, FaceSheets{}, {23, 2, 0, 11});  // the offset counts LSBs of the coordinate grid
  EXPECT_EQ(offset.moved({0.25, 0.5, 0.25}, 0).y, 0.5 - 2.0 / 2048);
}

Vec3 point_on(const Triangle& t, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.05, 0.95);
  double a = u(rng), b = u(rng);
  if (a + b > 1) a = 1 - a, b = 1 - b;
  return t.v0 + a * t.edge1() + b * t.edge2();
}

// What the fixes define, one face at a time.
std::vector<std::uint8_t> oracle(const std::vector<Triangle>& faces, const FaceSheets& sheets, const SegmentBatch& given,
                                 const SegmentFixOptions& o) {
  SegmentFixer fixer(faces, sheets, o);
  const std::vector<Triangle>& rounded = fixer.faces();
  SegmentBatch batch = given;
  fixer.adjust(batch);
  std::vector<std::uint8_t> blocked(batch.size(), 0);
  for (std::size_t s = 0; s < batch.size(); ++s) {
    for (int f = 0; f < static_cast<int>(faces.size()) && !blocked[s]; ++f) {
      const bool skip = o.neighbour_rings != 0 ? fixer.excluded(f, batch.source_face, batch.end_faces[s])
                                               : sheets.same(f, batch.source_face) || sheets.same(f, batch.end_faces[s]);
      if (skip) continue;
      blocked[s] = o.bits == 0 ? pipeline::segment_hits_ref(rounded[f], batch.start, batch.ends[s])
                               : pipeline::segment_hits(pipeline::make_face_record(rounded[f], o.bits),
                                                        pipeline::quantize_point(batch.start, o.bits),
                                                        pipeline::quantize_point(batch.ends[s], o.bits), o.bits);
    }
  }
  return blocked;
}

TEST(SegmentFixes, BothBitExactBackendsGiveTheDefinitionAtEveryWidth) {
  const Scene scene = small_torus_scene();
  const std::vector<Triangle> faces = scene.face_triangles();
  std::mt19937 rng(37);
  std::uniform_int_distribution<int> face(0, static_cast<int>(faces.size()) - 1);
  int cleared = 0, differs_from_unfixed = 0;
  for (int bits = 7; bits <= 31; ++bits) {
    for (const SegmentFixOptions fix : {SegmentFixOptions{bits, 0, 1}, SegmentFixOptions{bits, 2, 0}, SegmentFixOptions{bits, 1, 2},
                                        SegmentFixOptions{bits, 4, 1}, SegmentFixOptions{bits, 0, 0, bits > 7 ? std::max(7, bits - 1 - bits % 5) : 0},
                                        SegmentFixOptions{bits, 1, 1, bits > 7 ? 7 : 0}}) {
      FixedPointVisibility fixed(bits);
      FastFixedVisibility fast(bits, 2);
      FixedSegmentsVisibility fixed_fixes(fixed, fix), fast_fixes(fast, fix);
      fixed_fixes.load_faces(faces, scene.sheets);
      fast_fixes.load_faces(faces, scene.sheets);
      for (int round = 0; round < 3; ++round) {
        // Start on the torus (the last faces), ends anywhere, half of them on the torus near the start.
        SegmentBatch batch;
        batch.source_face = static_cast<int>(faces.size()) - 1 - face(rng) % 144;
        batch.start = point_on(faces[static_cast<std::size_t>(batch.source_face)], rng);
        for (int s = 0; s < 120; ++s) {
          const int f = s % 2 ? face(rng) : static_cast<int>(faces.size()) - 1 - face(rng) % 144;
          batch.ends.push_back(point_on(faces[static_cast<std::size_t>(f)], rng));
          batch.end_faces.push_back(f);
        }
        const std::vector<std::uint8_t> expected = oracle(faces, scene.sheets, batch, fix);
        std::vector<std::uint8_t> a, b, unfixed;
        fixed_fixes.submit(batch);
        fixed_fixes.collect(a);
        fast_fixes.submit(batch);
        fast_fixes.collect(b);
        ASSERT_EQ(a, expected) << bits << " bits, offset " << fix.offset_lsb << ", rings " << fix.neighbour_rings;
        ASSERT_EQ(b, expected) << bits << " bits, offset " << fix.offset_lsb << ", rings " << fix.neighbour_rings;
        fixed.submit(batch);
        fixed.collect(unfixed);
        differs_from_unfixed += unfixed != expected;
      }
      cleared += static_cast<int>(fixed_fixes.fixer()->segments_cleared());
      EXPECT_EQ(fixed_fixes.fixer()->segments_cleared(), fast_fixes.fixer()->segments_cleared());
      EXPECT_EQ(fixed_fixes.fixer()->tests_performed(), fast_fixes.fixer()->tests_performed());
    }
  }
  EXPECT_GT(cleared, 0);  // the neighbour rule had work to do
  EXPECT_GT(differs_from_unfixed, 0);
}

TEST(SegmentFixes, DoublePrecisionNeighbourRuleMatchesTheDefinition) {
  const Scene scene = small_torus_scene();
  const std::vector<Triangle> faces = scene.face_triangles();
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> face(0, static_cast<int>(faces.size()) - 1);
  FixedPointVisibility unused(15);
  const SegmentFixOptions fix{0, 0, 1};
  SegmentBatch batch;
  batch.source_face = static_cast<int>(faces.size()) - 5;
  batch.start = point_on(faces[static_cast<std::size_t>(batch.source_face)], rng);
  for (int s = 0; s < 200; ++s) {
    const int f = face(rng);
    batch.ends.push_back(point_on(faces[static_cast<std::size_t>(f)], rng));
    batch.end_faces.push_back(f);
  }
  std::vector<std::uint8_t> blocked(batch.size(), 0);
  for (std::size_t s = 0; s < batch.size(); ++s) {
    for (int f = 0; f < static_cast<int>(faces.size()); ++f) {
      if (!scene.sheets.same(f, batch.source_face) && !scene.sheets.same(f, batch.end_faces[s]))
        blocked[s] |= pipeline::segment_hits_ref(faces[f], batch.start, batch.ends[s]);
    }
  }
  SegmentFixer fixer(faces, scene.sheets, fix);
  fixer.recheck(batch, blocked);
  EXPECT_EQ(blocked, oracle(faces, scene.sheets, batch, fix));
}

// A whole solve with the fixes in SolverOptions: the brute-force and the culled backend agree on
// every radiosity bit, and on the host's re-tests.
TEST(SegmentFixes, SolvesAreBitIdenticalOnBothBackends) {
  const Scene scene = small_torus_scene(12, 6, 1);
  for (int bits : {7, 15, 23, 31}) {
    SolverOptions o;
    o.fixed_steps = 25;
    o.fixes = {bits, 2, 1, bits >= 15 ? bits - 4 : 0};
    FixedPointVisibility fixed(bits);
    FastFixedVisibility fast(bits, 2);
    const SolverResult a = ProgressiveRadiosity(scene, fixed, o).run();
    const SolverResult b = ProgressiveRadiosity(scene, fast, o).run();
    ASSERT_EQ(a.radiosity.size(), b.radiosity.size());
    for (std::size_t p = 0; p < a.radiosity.size(); ++p) ASSERT_EQ(a.radiosity[p].band, b.radiosity[p].band) << bits << " bits, patch " << p;
    EXPECT_EQ(a.fix_tests, b.fix_tests);
    EXPECT_EQ(a.fix_cleared, b.fix_cleared);
    EXPECT_EQ(a.blocked_segments, b.blocked_segments);
  }
}

}  // namespace
}  // namespace rc::test
