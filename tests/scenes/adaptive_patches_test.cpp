#include <gtest/gtest.h>

#include <vector>

#include "scenes/adaptive_patches.h"
#include "scenes/subdivide.h"

namespace rc {
namespace {

// Two faces (a unit square's two triangles), each split into 4 patches: 8 patches, grouped by face.
Scene two_faces() {
  Scene s;
  s.materials.push_back({"white", Spectrum::uniform(0.5), Spectrum{}});
  s.faces.push_back({Triangle{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0)}, 0, 0});
  s.faces.push_back({Triangle{Vec3(0, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)}, 0, 0});
  s.patches = make_patches(s.faces, 1);
  return s;
}

TEST(AdaptivePatches, TheGradientIsTheLargestDifferenceToACornerNeighbourOfTheSameFace) {
  Scene s = two_faces();
  s.patches = make_patches(s.faces, 2);  // 16 a face: patch 0 is the corner child of face 0's corner child
  ASSERT_EQ(s.patches.size(), 32u);
  std::vector<Spectrum> b(32, Spectrum::uniform(1.0));
  b[0] = Spectrum::uniform(3.0);
  b[16] = Spectrum::uniform(0.0);  // face 1's first patch: never compared with face 0's
  const std::vector<double> g = radiosity_gradients(s, b);
  // The four children of one split share corners with each other (midpoints), and with no patch
  // of the other children of their grandparent.
  for (int i = 0; i < 4; ++i) EXPECT_DOUBLE_EQ(g[i], (3.0 - 1.0) / 3.0) << i;
  for (int i = 4; i < 16; ++i) EXPECT_DOUBLE_EQ(g[i], 0.0) << i;
  for (int i = 16; i < 20; ++i) EXPECT_DOUBLE_EQ(g[i], 1.0 / 3.0) << i;
  for (int i = 20; i < 32; ++i) EXPECT_DOUBLE_EQ(g[i], 0.0) << i;
  EXPECT_EQ(radiosity_gradients(s, std::vector<Spectrum>(32)), std::vector<double>(32, 0.0));  // black: no gradient
  EXPECT_THROW(radiosity_gradients(s, std::vector<Spectrum>(31)), std::invalid_argument);
}

TEST(AdaptivePatches, TheSteepestPatchesSplitInPlaceIntoTheUniformChildren) {
  const Scene s = two_faces();
  std::vector<double> g(8, 0.0);
  g[6] = 0.9;
  g[1] = 0.5;
  g[2] = 0.5;  // a tie with patch 1: the lower index goes first
  const std::vector<Patch> p = split_steepest(s, g, 2, 3);
  ASSERT_EQ(p.size(), 8u + 2 * 3);
  // Patch 1 became four, where it was; patch 2 stayed; patch 6 became four.
  const std::vector<Triangle> children = split4(s.patches[1].tri);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(p[1 + i].tri.v0, children[i].v0);
    EXPECT_EQ(p[1 + i].face, 0);
    EXPECT_DOUBLE_EQ(p[1 + i].area, s.patches[1].area / 4);
  }
  EXPECT_EQ(p[5].tri.v0, s.patches[2].tri.v0);
  EXPECT_EQ(p[9].face, 1);  // face 0 now has 7 patches (0..6); patch 6 of face 1 became 9..12
  for (std::size_t i = 1; i < p.size(); ++i) EXPECT_LE(p[i - 1].face, p[i].face);
  Scene after = s;
  after.patches = p;
  EXPECT_EQ(patch_depth(after, after.patches[1]), 2);
  EXPECT_EQ(patch_depth(after, after.patches[0]), 1);
  // Patches at the depth limit are passed over: with limit 1 nothing may split.
  EXPECT_EQ(split_steepest(s, g, 2, 1).size(), 8u);
  EXPECT_EQ(split_steepest(s, g, 0, 3).size(), 8u);
}

}  // namespace
}  // namespace rc
