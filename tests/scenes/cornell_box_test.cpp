#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "scenes/cornell_box.h"
#include "scenes/normalise.h"
#include "scenes/prepare.h"
#include "scenes/subdivide.h"

namespace rc {
namespace {

double total_area(const std::vector<Face>& faces) {
  double a = 0;
  for (const Face& f : faces) a += f.tri.area();
  return a;
}

TEST(CornellBox, HasAllSurfacesWithTheCeilingCutAroundTheLight) {
  const Scene s = cornell_box();
  // 15 published quads (ceiling excluded) + 4 ceiling quads around the light, 2 triangles each.
  EXPECT_EQ(s.faces.size(), 38u);
  EXPECT_EQ(s.materials.size(), 4u);
  double ceiling = 0, light = 0;
  for (const Face& f : s.faces) {
    if (s.surface_names[f.surface] == "ceiling") ceiling += f.tri.area();
    if (s.surface_names[f.surface] == "light") light += f.tri.area();
  }
  EXPECT_NEAR(light, 130.0 * 105.0, 1e-6);
  EXPECT_NEAR(ceiling, 556.0 * 559.2 - 130.0 * 105.0, 1e-6);  // the hole is exactly the light
}

TEST(CornellBox, RoomSurfacesFaceInwardsAndBlocksOutwards) {
  const Scene s = cornell_box();
  const Vec3 room_centre(278, 274.4, 279.6);
  for (const Face& f : s.faces) {
    const std::string& name = s.surface_names[f.surface];
    const Vec3 to_centre = room_centre - f.tri.centroid();
    const double facing = glm::dot(f.tri.normal(), to_centre);
    if (name.find("block") == std::string::npos) {
      EXPECT_GT(facing, 0) << name;
    } else {
      const Vec3 block_centre = name.find("short") != std::string::npos ? Vec3(186, 82.5, 168.5) : Vec3(368.5, 165, 351.5);
      EXPECT_GT(glm::dot(f.tri.normal(), f.tri.centroid() - block_centre), 0) << name;
    }
  }
}

TEST(CornellBox, RgbBandMeansMatchTheDataSheet) {
  // The data sheet's "band means" row: white 0.734 0.736 0.698, red 0.576 0.083 0.056,
  // green 0.133 0.351 0.114, light 17.0 11.6 3.84 (rounded to 3 figures there).
  const Spectrum white = to_rgb_band_means(cornell_white());
  EXPECT_NEAR(white[0], 0.734, 0.0015);
  EXPECT_NEAR(white[1], 0.736, 0.0015);
  EXPECT_NEAR(white[2], 0.698, 0.0015);
  const Spectrum red = to_rgb_band_means(cornell_red());
  EXPECT_NEAR(red[0], 0.576, 0.0015);
  EXPECT_NEAR(red[1], 0.083, 0.0015);
  const Spectrum green = to_rgb_band_means(cornell_green());
  EXPECT_NEAR(green[1], 0.351, 0.0015);
  const Spectrum light = to_rgb_band_means(cornell_light_emission());
  EXPECT_NEAR(light[0], 17.0, 0.05);
  EXPECT_NEAR(light[1], 11.6, 0.05);
  EXPECT_NEAR(light[2], 3.84, 0.05);
}

TEST(Subdivision, UniformSplitMultipliesCountsAndKeepsAreasAndNormals) {
  const Scene s = cornell_box();
  const std::vector<Face> split = split_faces(s.faces, 2);
  ASSERT_EQ(split.size(), s.faces.size() * 16);
  EXPECT_NEAR(total_area(split), total_area(s.faces), 1e-6 * total_area(s.faces));
  for (std::size_t i = 0; i < split.size(); ++i) {
    const Face& parent = s.faces[i / 16];
    EXPECT_NEAR(glm::dot(split[i].tri.normal(), parent.tri.normal()), 1.0, 1e-12);
    EXPECT_NEAR(split[i].tri.area(), parent.tri.area() / 16, 1e-9 * parent.tri.area());
  }
}

TEST(Subdivision, PatchesTileTheirFace) {
  const Scene s = cornell_box();
  const std::vector<Patch> patches = make_patches(s.faces, 3);
  ASSERT_EQ(patches.size(), s.faces.size() * 64);
  for (std::size_t i = 0; i < patches.size(); ++i) {
    const Patch& p = patches[i];
    const Face& f = s.faces[p.face];
    EXPECT_EQ(p.face, static_cast<int>(i / 64));
    EXPECT_NEAR(p.area, f.tri.area() / 64, 1e-9 * f.tri.area());
    EXPECT_NEAR(glm::dot(p.normal, f.tri.normal()), 1.0, 1e-12);
    EXPECT_NEAR(glm::dot(p.centre - f.tri.v0, f.tri.normal()), 0.0, 1e-9);  // centre on the face plane
  }
}

// --patch-size: each face split until its patches' edges fit; large faces get more levels than
// small ones, every patch's longest edge is at most the size, and the patches still tile the faces.
TEST(Subdivision, PatchSizeSplitsEachFaceUntilItsEdgesFit) {
  SceneOptions options;
  options.patch_size = 0.1;
  const Scene s = prepare_scene(options).scene;
  std::vector<double> area(s.faces.size(), 0.0);
  std::vector<int> count(s.faces.size(), 0);
  for (const Patch& p : s.patches) {
    const Triangle& t = p.tri;
    const double longest = std::max({glm::length(t.v1 - t.v0), glm::length(t.v2 - t.v1), glm::length(t.v0 - t.v2)});
    EXPECT_LE(longest, 0.1 * (1 + 1e-12));
    area[p.face] += p.area;
    ++count[p.face];
  }
  int fewest = count[0], most = count[0];
  for (std::size_t f = 0; f < s.faces.size(); ++f) {
    EXPECT_NEAR(area[f], s.faces[f].tri.area(), 1e-9 * s.faces[f].tri.area());
    EXPECT_EQ(count[f], 1 << (2 * levels_for_size(s.faces[f].tri, 0.1)));
    fewest = std::min(fewest, count[f]);
    most = std::max(most, count[f]);
  }
  EXPECT_LT(fewest, most);  // the box's small block faces get fewer patches than its walls
  EXPECT_EQ(levels_for_size(s.faces[0].tri, 10.0), 0);
  EXPECT_THROW(levels_for_size(s.faces[0].tri, 0.0), std::invalid_argument);
}

// Eight levels halve the longest edge exactly eight times: a size of exactly edge / 256 is met, any
// smaller size is an error (it used to be met silently with edge / 256).
TEST(Subdivision, PatchSizeBeyondEightLevelsIsAnError) {
  const Scene s = prepare_scene(SceneOptions{}).scene;
  const Triangle& t = s.faces[0].tri;
  const double longest = std::max({glm::length(t.v1 - t.v0), glm::length(t.v2 - t.v1), glm::length(t.v0 - t.v2)});
  EXPECT_EQ(levels_for_size(t, std::ldexp(longest, -kMaxSplitLevels)), kMaxSplitLevels);
  EXPECT_THROW(levels_for_size(t, std::nextafter(std::ldexp(longest, -kMaxSplitLevels), 0.0)), std::invalid_argument);
  EXPECT_THROW(levels_for_size(t, 1e-300), std::invalid_argument);
}

TEST(Subdivision, RefineToCountIsExactAndDeterministic) {
  const Scene s = cornell_box();
  const std::vector<Face> a = refine_to_count(s.faces, 70);
  const std::vector<Face> b = refine_to_count(s.faces, 70);
  ASSERT_EQ(a.size(), 70u);
  EXPECT_NEAR(total_area(a), total_area(s.faces), 1e-6 * total_area(s.faces));
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].tri.v0, b[i].tri.v0);
    EXPECT_EQ(a[i].tri.v2, b[i].tri.v2);
  }
  EXPECT_THROW(refine_to_count(s.faces, 10), std::invalid_argument);
  // The paper's counts follow: 70 faces, then 4x and 16x.
  EXPECT_EQ(split_faces(a, 1).size(), 280u);
  EXPECT_EQ(split_faces(a, 2).size(), 1120u);
  EXPECT_EQ(make_patches(a, 3).size(), 4480u);
}

TEST(Normalisation, EveryCoordinateFitsUnsignedFixedPointAtEveryWidth) {
  SceneOptions options;
  options.face_levels = 1;
  options.patch_levels = 1;
  const Scene s = prepare_scene(options).scene;
  double lo = 1, hi = 0;
  for (const Face& f : s.faces) {
    for (const Vec3& v : {f.tri.v0, f.tri.v1, f.tri.v2}) {
      for (int k = 0; k < 3; ++k) {
        lo = std::min(lo, v[k]);
        hi = std::max(hi, v[k]);
      }
    }
  }
  EXPECT_EQ(lo, 0.0);
  EXPECT_EQ(hi, kMaxNormalisedCoordinate);  // the largest extent lands exactly here
  EXPECT_LT(hi, 1.0);
  EXPECT_LT(std::floor(hi * 2147483648.0), 2147483648.0);  // fits 0.31 unsigned
  // The transform is recorded: mapping a world corner reproduces the normalised one.
  const Scene world = cornell_box();
  EXPECT_NEAR(s.normalisation.apply(world.faces[0].tri.v0).x, s.faces[0].tri.v0.x, 1e-12);
}

}  // namespace
}  // namespace rc
