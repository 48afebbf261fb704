#include <gtest/gtest.h>

#include "host_sw/radiosity/float_visibility.h"
#include "host_sw/radiosity/radiosity.h"
#include "tests/common/simple_scenes.h"

namespace rc {
namespace {

// Two facing triangles (source at z = 0, destination at z = 1) and optionally a blocker between.
std::vector<Triangle> facing_pair(bool with_blocker) {
  std::vector<Triangle> faces = {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 0, 1}, {0, 1, 1}, {1, 0, 1}}};
  if (with_blocker) faces.push_back({{-1, -1, 0.5}, {2, -1, 0.5}, {-1, 2, 0.5}});
  return faces;
}

SegmentBatch centre_to_centre(const std::vector<Triangle>& faces) {
  SegmentBatch batch;
  batch.start = faces[0].centroid();
  batch.source_face = 0;
  batch.ends = {faces[1].centroid()};
  batch.end_faces = {1};
  return batch;
}

TEST(OwnFaceRule, SegmentNeverHitsItsOwnSourceOrDestinationFace) {
  FloatVisibility v;
  std::vector<std::uint8_t> blocked;
  v.load_faces(facing_pair(false));
  v.submit(centre_to_centre(facing_pair(false)));
  v.collect(blocked);
  ASSERT_EQ(blocked.size(), 1u);
  EXPECT_EQ(blocked[0], 0);
  EXPECT_EQ(v.tests_performed(), 0u);  // own faces are not even tested

  // Treating the same end faces as strangers: the end points lie exactly on them (t = 0, t = det),
  // which the strict test also rejects in exact arithmetic. The rule makes this independent of rounding.
  SegmentBatch anonymous = centre_to_centre(facing_pair(false));
  anonymous.source_face = -1;
  anonymous.end_faces = {-1};
  v.submit(anonymous);
  v.collect(blocked);
  EXPECT_EQ(v.tests_performed(), 2u);
}

TEST(OwnFaceRule, AnotherFaceBetweenStillBlocks) {
  FloatVisibility v;
  std::vector<std::uint8_t> blocked;
  v.load_faces(facing_pair(true));
  v.submit(centre_to_centre(facing_pair(true)));
  v.collect(blocked);
  EXPECT_EQ(blocked[0], 1);
}

// Receivers behind the shooter or facing away get no segment at all.
TEST(Receivers, BehindOrFacingAwayGetNoSegment) {
  SceneBuilder b("back-to-back");
  const int lamp = b.add_material({"lamp", Spectrum::uniform(0.5), Spectrum::uniform(1)});
  const Vec3 x(1, 0, 0), y(0, 1, 0);
  b.add_surface("up", lamp, test::square({0, 0, 0}, x, y), "test");         // faces +z
  b.add_surface("down", lamp, test::square({0, 0, -0.1}, y, x), "test");   // faces -z, behind it
  b.add_surface("above", lamp, test::square({0, 0, 1}, x, y), "test");     // faces +z, away from "up"
  Scene s = b.build();
  normalise(s);
  s.patches = make_patches(s.faces, 0);
  FloatVisibility v;
  SolverOptions options;
  options.fixed_steps = 1;
  const SolverResult r = ProgressiveRadiosity(s, v, options).run();
  EXPECT_EQ(r.segments, 0u);  // from the first shooter nothing is in front and facing it
  EXPECT_EQ(r.receivers_skipped, s.patches.size() - 1);
}

}  // namespace
}  // namespace rc
