// Sheets (scenes/sheets.h) and finding them (scenes/sheet_finder.h): faces back to back are one
// sheet, found by geometry at the documented tolerances, made contiguous; everything else, the
// Cornell Box included, is left as it was.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "scenes/prepare.h"
#include "scenes/scene_builder.h"
#include "scenes/scene_file.h"
#include "scenes/sheet_finder.h"
#include "tests/common/simple_scenes.h"

namespace rc::test {
namespace {

const std::string kExamples = RC_SOURCE_DIR "/scenes/examples/";

Face face(const Vec3& a, const Vec3& b, const Vec3& c, int surface = 0) { return {{a, b, c}, 0, surface}; }

TEST(FaceSheets, OneSidedByDefaultAndContiguousOtherwise) {
  const FaceSheets none;
  EXPECT_TRUE(none.one_sided());
  EXPECT_EQ(none.first(5), 5);
  EXPECT_EQ(none.end(5), 6);
  EXPECT_TRUE(none.same(3, 3));
  EXPECT_FALSE(none.same(3, 4));
  EXPECT_FALSE(none.same(-1, 0));

  const FaceSheets s({0, 1, 1, 1, 4, 5, 5});
  EXPECT_FALSE(s.one_sided());
  EXPECT_EQ(s.first(3), 1);
  EXPECT_EQ(s.end(1), 4);
  EXPECT_EQ(s.size_of(2), 3);
  EXPECT_EQ(s.size_of(4), 1);
  EXPECT_TRUE(s.same(1, 3));
  EXPECT_FALSE(s.same(3, 4));
  EXPECT_EQ(s.first(-1), -1);  // "no face" is nobody's sheet
  EXPECT_EQ(s.first(7), 7);
  EXPECT_EQ(s.shared_sheets(), 2u);
  EXPECT_EQ(s.faces_in_shared_sheets(), 5u);
  // Every face its own sheet is stored as the one-sided map.
  EXPECT_TRUE(FaceSheets({0, 1, 2}).one_sided());

  EXPECT_THROW(FaceSheets({0, 0, 1, 0}), std::invalid_argument);  // not contiguous
  EXPECT_THROW(FaceSheets({1, 1}), std::invalid_argument);        // named by a later face

  // A card holding faces 2..5: the sheet [1, 4) keeps its part [2, 4), renumbered [0, 2).
  const FaceSheets card = s.restricted(2, 4);
  EXPECT_EQ(card.first_of_face(), (std::vector<int>{0, 0, 2, 3}));
}

TEST(FindTwins, ExactTwinsAndTheirToleranceButNothingElse) {
  const Vec3 a(0.1, 0.2, 0.3), b(0.6, 0.2, 0.3), c(0.2, 0.7, 0.4);
  // A face and its twin (winding turned): one pair.
  EXPECT_EQ(find_twin_faces({face(a, b, c), face(a, c, b)}), (std::vector<std::pair<int, int>>{{0, 1}}));
  // The twin with its vertices in another rotation, one of them off by 1e-12: still twins.
  EXPECT_EQ(find_twin_faces({face(a, b, c), face(c + Vec3(1e-12, 0, 0), b, a)}).size(), 1u);
  // Facing the same way (the Cornell light in its ceiling): not twins.
  EXPECT_TRUE(find_twin_faces({face(a, b, c), face(a, b, c)}).empty());
  // Back to back but 1e-6 apart (beyond kSheetDistance = 1e-9): two surfaces, not one.
  const Vec3 n = glm::normalize(glm::cross(b - a, c - a)) * 1e-6;
  EXPECT_TRUE(find_twin_faces({face(a, b, c), face(a + n, c + n, b + n)}).empty());
  // Turned by 1e-4 rad (beyond kSheetAngle = 1e-6): not twins.
  EXPECT_TRUE(find_twin_faces({face(a, b, c), face(a, c, b + Vec3(0, 0, 5e-5))}).empty());
  // Coplanar, opposite, but only touching along an edge: no shared area.
  const Vec3 d = b + c - a;
  EXPECT_TRUE(find_twin_faces({face(a, b, c), face(b, c, d)}).empty());
  // Coplanar, opposite, overlapping in part: twins.
  const Vec3 mid = (a + b + c) / 3.0;
  EXPECT_EQ(find_twin_faces({face(a, b, c), face(mid, mid + (c - a), mid + (b - a))}).size(), 1u);
}

// A two-sided quad written as two quads split along different diagonals: four triangles that overlap
// pairwise, one sheet, made contiguous; the faces before and after keep their order.
TEST(FindSheets, TwoSidedQuadOfOtherDiagonalsIsOneContiguousSheet) {
  SceneBuilder builder("t");
  const int m = builder.add_material({"grey", Spectrum::uniform(0.5), Spectrum::uniform(1.0)});
  const Vec3 p0(0, 0, 0), p1(1, 0, 0), p2(1, 1, 0.2), p3(0, 1, 0.2);
  builder.add_surface("front", m, {p0, p1, p2, p3}, "t:1");   // split along p0-p2
  builder.add_surface("other", m, {Vec3(0, 0, 1), Vec3(0, 1, 1), Vec3(1, 1, 1)}, "t:2");
  builder.add_surface("back", m, {p1, p0, p3, p2}, "t:3");    // split along p1-p3
  Scene scene = builder.build();
  ASSERT_EQ(scene.faces.size(), 5u);
  find_sheets(scene);
  EXPECT_EQ(scene.sheets.first_of_face(), (std::vector<int>{0, 0, 0, 0, 4}));
  EXPECT_EQ(scene.surface_name(scene.faces[4].surface), "other");  // moved after the sheet
  for (int f = 0; f < 4; ++f) EXPECT_NE(scene.surface_name(scene.faces[f].surface), "other");
}

TEST(FindSheets, TheCornellBoxHasNoneAndKeepsItsFaces) {
  SceneOptions o;
  o.patch_levels = 0;
  o.face_target = 70;
  const Scene scene = prepare_scene(o).scene;
  EXPECT_TRUE(scene.sheets.one_sided());
  Scene again = cornell_box(0, 70);
  EXPECT_TRUE(again.sheets.one_sided());
}

// The example scene's plate (one 'two-sided quad'): its four faces are one sheet after any rotation,
// translation or scale of the whole scene.
TEST(FindSheets, TiltedPlateIsOneSheetHoweverTheSceneIsPlaced) {
  const LoadedScene loaded = load_scene_file(kExamples + "tilted-plate.scene");
  std::mt19937 random(7);
  std::uniform_real_distribution<double> angle(0, 2 * M_PI);
  for (int trial = 0; trial < 20; ++trial) {
    Scene scene = loaded.scene;
    const glm::dmat3 turn = glm::dmat3(glm::rotate(glm::dmat4(1.0), angle(random), glm::normalize(Vec3(1, 2, 3 + trial))));
    const double scale = std::pow(10.0, trial % 7 - 3);
    for (Face& f : scene.faces) {
      for (Vec3* v : {&f.tri.v0, &f.tri.v1, &f.tri.v2}) *v = turn * (*v) * scale + Vec3(trial, -3.5, 1e3);
    }
    scene.camera.position = turn * scene.camera.position * scale + Vec3(trial, -3.5, 1e3);
    scene.camera.look_at = turn * scene.camera.look_at * scale + Vec3(trial, -3.5, 1e3);
    scene.camera.up = turn * scene.camera.up;
    normalise(scene);
    find_sheets(scene);
    SCOPED_TRACE("trial " + std::to_string(trial));
    EXPECT_EQ(scene.sheets.shared_sheets(), 1u);
    EXPECT_EQ(scene.sheets.faces_in_shared_sheets(), 4u);
  }
}

TEST(FindSheets, ManyCoplanarFacesCostLittleAndSplitTwinsPairUp) {
  // A two-sided plane of 2 x 40 x 40 triangles on each side: 6400 faces in one plane bucket; each
  // cell (a surface of its own) is one sheet of four triangles, its two halves and their backs.
  SceneBuilder builder("grid");
  const int m = builder.add_material({"grey", Spectrum::uniform(0.5), Spectrum::uniform(1.0)});
  const int n = 40;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const Vec3 p(i, j, 0), q(i + 1, j, 0), r(i + 1, j + 1, 0), s(i, j + 1, 0);
      builder.add_two_sided_surface("cell", m, {p, q, r, s}, "grid");
    }
  }
  Scene scene = builder.build();
  normalise(scene);
  find_sheets(scene);
  EXPECT_EQ(scene.sheets.shared_sheets(), static_cast<std::size_t>(n * n));
  EXPECT_EQ(scene.sheets.faces_in_shared_sheets(), static_cast<std::size_t>(4 * n * n));
}

TEST(FindSheets, RefusesASceneWithPatches) {
  Scene scene = cornell_box(0);
  EXPECT_THROW(find_sheets(scene), std::logic_error);
}

TEST(SceneFile, TwoSidedSurfacesAreTheSurfaceAndItsBack) {
  const LoadedScene loaded = parse_scene_text(
      "material m reflectance 0.5 0.5 0.5 emission 1 1 1\n"
      "two-sided quad q m  0 0 0  1 0 0  1 1 0  0 1 0\n"
      "two-sided tri t m  0 0 1  1 0 1  0 1 1\n",
      "two.scene");
  const Scene& s = loaded.scene;
  ASSERT_EQ(s.faces.size(), 6u);
  EXPECT_EQ(s.surface_names, (std::vector<std::string>{"q", "q (back)", "t", "t (back)"}));
  // The back's triangles are the front's, wound the other way.
  EXPECT_EQ(s.faces[2].tri.v0, s.faces[0].tri.v0);
  EXPECT_EQ(s.faces[2].tri.cross(), -s.faces[1].tri.cross());
  EXPECT_EQ(s.faces[3].tri.cross(), -s.faces[0].tri.cross());
  EXPECT_EQ(s.faces[5].tri.cross(), -s.faces[4].tri.cross());
  try {
    parse_scene_text("material m reflectance 0.5 0.5 0.5\ntwo-sided box m 0 0 0\n", "bad.scene");
    FAIL();
  } catch (const SceneFileError& e) {
    EXPECT_STREQ(e.what(), "bad.scene:2: 'two-sided' is followed by 'box' (expected quad or tri)");
  }
}

}  // namespace
}  // namespace rc::test
