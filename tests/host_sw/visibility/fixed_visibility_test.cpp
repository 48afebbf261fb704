// FixedPointVisibility: the CPU backend with the pipeline's arithmetic answers exactly what a
// brute-force loop of segment_hits answers under the own-face rule, and counts its tests.
#include <gtest/gtest.h>

#include <random>
#include <stdexcept>

#include "host_sw/visibility/fixed_visibility.h"
#include "scenes/cornell_box.h"
#include "scenes/normalise.h"
#include "pipeline/fixed_mt.h"
#include "tests/host_sw/visibility/random_batch.h"

namespace rc {
namespace {

using test::RandomBatch;
using test::random_batch;

std::vector<std::uint8_t> brute_force(const RandomBatch& s, int bits) {
  const pipeline::FixedVec3 start = pipeline::quantize_point(s.batch.start, bits);
  std::vector<std::uint8_t> blocked(s.batch.size(), 0);
  for (std::size_t i = 0; i < s.batch.size(); ++i) {
    const pipeline::FixedVec3 end = pipeline::quantize_point(s.batch.ends[i], bits);
    for (std::size_t f = 0; f < s.faces.size(); ++f) {
      if (is_own_surface(FaceSheets{}, s.batch, i, static_cast<int>(f))) continue;
      blocked[i] |= pipeline::segment_hits(pipeline::make_face_record(s.faces[f], bits), start, end, bits);
    }
  }
  return blocked;
}

TEST(PipelineFixedVisibility, MatchesBruteForceSegmentHitsAtEveryPathWidth) {
  const RandomBatch s = random_batch(40, 300, 1);
  for (int bits : {7, 15, 16, 31}) {
    FixedPointVisibility v(bits);
    v.load_faces(s.faces);
    v.submit(s.batch);
    std::vector<std::uint8_t> blocked;
    v.collect(blocked);
    const std::vector<std::uint8_t> expected = brute_force(s, bits);
    EXPECT_EQ(blocked, expected) << bits << " bits";
    std::size_t count = 0;
    for (auto b : expected) count += b;
    EXPECT_GT(count, 10u) << "scene too sparse to test anything";
    EXPECT_LT(count, s.batch.size());
  }
}

// One blocker between a source and a receiver: blocked, unless the blocker is one of the
// segment's own faces.
TEST(PipelineFixedVisibility, OwnFacesNeverBlock) {
  const std::vector<Triangle> faces = {
      {{0.1, 0.1, 0.1}, {0.9, 0.1, 0.1}, {0.1, 0.9, 0.1}},  // 0: source, z = 0.1
      {{0.1, 0.1, 0.5}, {0.9, 0.1, 0.5}, {0.1, 0.9, 0.5}},  // 1: blocker, z = 0.5
      {{0.1, 0.1, 0.9}, {0.9, 0.1, 0.9}, {0.1, 0.9, 0.9}},  // 2: receiver, z = 0.9
  };
  FixedPointVisibility v(15);
  v.load_faces(faces);
  SegmentBatch batch;
  batch.source_face = 0;
  batch.start = {0.3, 0.3, 0.1};
  batch.ends = {{0.3, 0.3, 0.9}, {0.3, 0.3, 0.9}, {0.3, 0.3, 0.9}};
  batch.end_faces = {2, 1, 0};  // the same segment, labelled with different end faces
  v.submit(batch);
  std::vector<std::uint8_t> blocked;
  v.collect(blocked);
  EXPECT_EQ(blocked, (std::vector<std::uint8_t>{1, 0, 1}));
  batch.source_face = 1;  // now the blocker is everyone's source face
  v.submit(batch);
  v.collect(blocked);
  EXPECT_EQ(blocked, (std::vector<std::uint8_t>{0, 0, 0}));
}

TEST(PipelineFixedVisibility, CountsEveryTestedPairExceptOwnFaces) {
  const RandomBatch s = random_batch(25, 120, 2);
  FixedPointVisibility v(23);
  v.load_faces(s.faces);
  v.submit(s.batch);
  std::uint64_t expected = 0;
  for (std::size_t i = 0; i < s.batch.size(); ++i)
    for (std::size_t f = 0; f < s.faces.size(); ++f) expected += !is_own_surface(FaceSheets{}, s.batch, i, static_cast<int>(f));
  EXPECT_EQ(v.tests_performed(), expected);
  v.submit(s.batch);  // the count accumulates over batches
  EXPECT_EQ(v.tests_performed(), 2 * expected);
}

TEST(PipelineFixedVisibility, ValidatesWidthAndBatch) {
  EXPECT_THROW(FixedPointVisibility(6), std::invalid_argument);
  EXPECT_THROW(FixedPointVisibility(32), std::invalid_argument);
  FixedPointVisibility v(31);
  EXPECT_EQ(v.frac_bits(), 31);
  EXPECT_EQ(v.name(), "fixed");
  v.load_faces({{{0.1, 0.1, 0.5}, {0.9, 0.1, 0.5}, {0.1, 0.9, 0.5}}});
  SegmentBatch batch;
  batch.start = {0.3, 0.3, 0.1};
  batch.ends = {{0.3, 0.3, 0.9}};
  EXPECT_THROW(v.submit(batch), std::invalid_argument);  // end_faces missing
  batch.end_faces = {-1};
  batch.ends[0].z = 1.0;  // outside the normalised scene
  EXPECT_THROW(v.submit(batch), std::out_of_range);
  batch.ends[0].z = 0.9;
  v.submit(batch);
  std::vector<std::uint8_t> blocked;
  v.collect(blocked);
  EXPECT_EQ(blocked, std::vector<std::uint8_t>{1});
  batch.ends.clear();
  batch.end_faces.clear();
  v.submit(batch);  // an empty batch is fine
  v.collect(blocked);
  EXPECT_TRUE(blocked.empty());
}

// The Cornell box keeps every face at every width; a room beside a mesh ten million times
// farther away than the room is wide loses the room's faces (they block nothing).
TEST(FacesWithoutArea, NoneInTheCornellBoxAtAnyWidthButAFarMeshTakesTheRoom) {
  Scene box = cornell_box();
  normalise(box);
  for (int bits : {7, 15, 31}) EXPECT_TRUE(faces_without_area(box.faces, bits).empty()) << bits;
  Scene far = cornell_box();
  Face distant = far.faces.front();
  for (Vec3* v : {&distant.tri.v0, &distant.tri.v1, &distant.tri.v2}) *v = *v + Vec3(1e7, 0, 0);
  far.faces.push_back(distant);
  normalise(far);
  const std::vector<std::size_t> lost = faces_without_area(far.faces, 15);
  EXPECT_FALSE(lost.empty());                  // the blocks' small faces, 300 units per grid step
  EXPECT_LT(lost.size(), far.faces.size());     // the walls, 556 units across, keep some area
  EXPECT_TRUE(faces_without_area(far.faces, 31).empty());  // 2^-31 of 1e7 is 0.005 units: the room survives
}

}  // namespace
}  // namespace rc
