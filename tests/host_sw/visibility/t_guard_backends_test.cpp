// The guard band on t in the bit-exact software backends: the brute-force one (FixedPointVisibility) and
// the culled one (FastFixedVisibility, whose hit regions are derived without the guard) give the
// definition, face by face, at every width 7..31 with g in {1, 2, 4}, alone and under the neighbour
// rule (whose host re-tests use the guard too); whole solves agree on every bit; and the factory refuses
// a guard where it does not apply.
#include <gtest/gtest.h>

#include <random>
#include <stdexcept>

#include "host_sw/radiosity/radiosity.h"
#include "host_sw/radiosity/segment_fixes.h"
#include "host_sw/visibility/fast_visibility.h"
#include "host_sw/visibility/fixed_visibility.h"
#include "host_sw/visibility/visibility_factory.h"
#include "pipeline/fixed_mt.h"
#include "tests/common/small_torus_scene.h"

namespace rc::test {
namespace {

Vec3 point_on(const Triangle& t, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.05, 0.95);
  double a = u(rng), b = u(rng);
  if (a + b > 1) a = 1 - a, b = 1 - b;
  return t.v0 + a * t.edge1() + b * t.edge2();
}

// The guarded pipeline's answer, one face at a time (own sheets skipped).
std::vector<std::uint8_t> definition(const std::vector<Triangle>& faces, const FaceSheets& sheets, const SegmentBatch& batch,
                                     int bits, int g) {
  std::vector<std::uint8_t> blocked(batch.size(), 0);
  const pipeline::FixedVec3 start = pipeline::quantize_point(batch.start, bits);
  for (std::size_t s = 0; s < batch.size(); ++s) {
    for (int f = 0; f < static_cast<int>(faces.size()) && !blocked[s]; ++f) {
      if (sheets.same(f, batch.source_face) || sheets.same(f, batch.end_faces[s])) continue;
      blocked[s] = pipeline::segment_hits(pipeline::make_face_record(faces[f], bits), start,
                                          pipeline::quantize_point(batch.ends[s], bits), bits, g);
    }
  }
  return blocked;
}

TEST(TGuardBackends, FixedAndCulledBackendsGiveTheDefinitionAtEveryWidth) {
  const Scene scene = small_torus_scene();
  const std::vector<Triangle> faces = scene.face_triangles();
  std::mt19937 rng(3737);
  std::uniform_int_distribution<int> face(0, static_cast<int>(faces.size()) - 1);
  std::size_t differs_from_unguarded = 0, blocked_total = 0;
  for (int bits = 7; bits <= 31; ++bits) {
    for (int g : {1, 2, 4}) {
      FixedPointVisibility fixed(bits, g), unguarded(bits);
      FastFixedVisibility fast(bits, 2, g);
      EXPECT_EQ(fixed.t_guard(), g);
      EXPECT_EQ(fast.t_guard(), g);
      for (VisibilityBackend* v : {static_cast<VisibilityBackend*>(&fixed), static_cast<VisibilityBackend*>(&fast),
                                   static_cast<VisibilityBackend*>(&unguarded)})
        v->load_faces(faces, scene.sheets);
      for (int round = 0; round < 2; ++round) {
        // Start on the torus (the last faces), ends anywhere, half of them on the torus (neighbours, small faces).
        SegmentBatch batch;
        batch.source_face = static_cast<int>(faces.size()) - 1 - face(rng) % 144;
        batch.start = point_on(faces[static_cast<std::size_t>(batch.source_face)], rng);
        for (int s = 0; s < 160; ++s) {
          const int f = s % 2 ? face(rng) : static_cast<int>(faces.size()) - 1 - face(rng) % 144;
          batch.ends.push_back(point_on(faces[static_cast<std::size_t>(f)], rng));
          batch.end_faces.push_back(f);
        }
        const std::vector<std::uint8_t> expected = definition(faces, scene.sheets, batch, bits, g);
        std::vector<std::uint8_t> a, b, c;
        fixed.submit(batch);
        fixed.collect(a);
        fast.submit(batch);
        fast.collect(b);
        unguarded.submit(batch);
        unguarded.collect(c);
        ASSERT_EQ(a, expected) << bits << " bits, g " << g;
        ASSERT_EQ(b, expected) << bits << " bits, g " << g;
        for (std::size_t s = 0; s < c.size(); ++s) {
          ASSERT_TRUE(!a[s] || c[s]) << "a guard only removes hits";
          differs_from_unguarded += a[s] != c[s];
          blocked_total += a[s];
        }
      }
    }
  }
  EXPECT_GT(differs_from_unguarded, 0u);  // the guard changed answers
  EXPECT_GT(blocked_total, 1000u);
}

// The neighbour rule re-tests on the host: with a guard those re-tests are the guarded pipeline's.
TEST(TGuardBackends, SolvesWithTheGuardAreBitIdenticalOnBothBackends) {
  const Scene scene = small_torus_scene(12, 6, 1);
  std::size_t changed = 0;
  for (int bits : {7, 15, 23, 31}) {
    for (int g : {1, 2, 4}) {
      SolverOptions o;
      o.fixed_steps = 20;
      o.fixes.bits = bits;
      o.fixes.t_guard = g;
      o.fixes.neighbour_rings = g == 2 ? 1 : 0;
      FixedPointVisibility fixed(bits, g), plain(bits);
      FastFixedVisibility fast(bits, 2, g);
      const SolverResult a = ProgressiveRadiosity(scene, fixed, o).run();
      const SolverResult b = ProgressiveRadiosity(scene, fast, o).run();
      ASSERT_EQ(a.radiosity.size(), b.radiosity.size());
      for (std::size_t p = 0; p < a.radiosity.size(); ++p) ASSERT_EQ(a.radiosity[p].band, b.radiosity[p].band) << bits << " bits, g " << g;
      EXPECT_EQ(a.blocked_segments, b.blocked_segments);
      EXPECT_EQ(a.fix_tests, b.fix_tests);
      SolverOptions unguarded = o;
      unguarded.fixes.t_guard = 0;
      changed += ProgressiveRadiosity(scene, plain, unguarded).run().blocked_segments != a.blocked_segments;
    }
  }
  EXPECT_GT(changed, 0u);
}

TEST(TGuardBackends, TheFactoryRefusesAGuardWhereItDoesNotApply) {
  EXPECT_NO_THROW(make_software_visibility("fixed", 15, 0, 4));
  EXPECT_NO_THROW(make_software_visibility("fast", 15, 1, 255));
  EXPECT_THROW(make_software_visibility("float", 15, 0, 1), std::invalid_argument);
  EXPECT_THROW(make_software_visibility("float:8,23", 15, 0, 1), std::invalid_argument);
  EXPECT_THROW(make_software_visibility("fixed", 15, 0, 256), std::invalid_argument);
  EXPECT_THROW(make_software_visibility("fast", 15, 1, -1), std::invalid_argument);
  EXPECT_NO_THROW(make_software_visibility("float", 15, 0, 0));
  // The solver's re-tests need a width to count the guard's LSBs in.
  const std::vector<Triangle> faces = {{{0.1, 0.5, 0.1}, {0.9, 0.5, 0.1}, {0.1, 0.5, 0.9}}};
  SegmentFixOptions o;
  o.t_guard = 1;
  EXPECT_THROW(SegmentFixer(faces, FaceSheets{}, o), std::invalid_argument);
  o.bits = 15;
  o.t_guard = 256;
  EXPECT_THROW(SegmentFixer(faces, FaceSheets{}, o), std::invalid_argument);
}

}  // namespace
}  // namespace rc::test
