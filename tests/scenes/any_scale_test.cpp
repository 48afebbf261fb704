// A scene loads, refines and normalises the same at any finite size: scaled by a power of two the
// normalised faces are bit-identical to the unit-size scene's; scaled by 1e200 or 1e-300 (each
// coordinate then rounded once when the scaled text is written) they agree within 8 units in the
// last place of 1. Coordinates that are not finite, and scenes below the normal doubles, are errors.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "scenes/normalise.h"
#include "scenes/prepare.h"
#include "scenes/scene_file.h"

namespace rc {
namespace {

// A lit room with a block and a camera (docs/scenes.md's format), every coordinate times k.
std::string room_text(double k) {
  const double quads[][12] = {
      {2, 0, 0, 0, 0, 0, 0, 0, 2, 2, 0, 2},                      // floor
      {2, 2, 0, 2, 2, 2, 0, 2, 2, 0, 2, 0},                      // ceiling
      {2, 0, 2, 0, 0, 2, 0, 2, 2, 2, 2, 2},                      // back
      {0, 0, 0, 0, 2, 0, 0, 2, 2, 0, 0, 2},                      // left
      {1.2, 1.99, 0.8, 1.2, 1.99, 1.2, 0.8, 1.99, 1.2, 0.8, 1.99, 0.8},  // lamp
      {0.7, 0, 1.1, 0.7, 0.6, 1.1, 1.3, 0.6, 1.1, 1.3, 0, 1.1},  // block front
  };
  const char* names[] = {"floor", "ceiling", "back", "left", "lamp", "block"};
  std::string text = "material white reflectance 0.7 0.7 0.7\nmaterial lamp reflectance 0.5 0.5 0.5 emission 9 9 9\n";
  char line[512];
  for (int q = 0; q < 6; ++q) {
    std::string words = std::string("quad ") + names[q] + (q == 4 ? " lamp" : " white");
    for (double c : quads[q]) {
      std::snprintf(line, sizeof line, " %.17g", c * k);
      words += line;
    }
    text += words + "\n";
  }
  std::snprintf(line, sizeof line, "camera %.17g %.17g %.17g  %.17g %.17g %.17g  0 1 0  50\n", 1 * k, 1 * k, -3 * k, 1 * k,
                1 * k, 0 * k);
  return text + line;
}

class AnyScale : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() / ("rc_any_scale_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  Scene prepared(double k, int face_target = 0) {
    const std::string path = (dir_ / "room.scene").string();
    std::ofstream(path) << room_text(k);
    SceneOptions o;
    o.file = path;
    o.face_target = face_target;
    o.patch_levels = 1;
    return prepare_scene(o).scene;
  }

  std::filesystem::path dir_;
};

void expect_faces_within(const Scene& a, const Scene& b, double tolerance, const std::string& what) {
  ASSERT_EQ(a.faces.size(), b.faces.size()) << what;
  for (std::size_t f = 0; f < a.faces.size(); ++f) {
    const Vec3 va[3] = {a.faces[f].tri.v0, a.faces[f].tri.v1, a.faces[f].tri.v2};
    const Vec3 vb[3] = {b.faces[f].tri.v0, b.faces[f].tri.v1, b.faces[f].tri.v2};
    for (int v = 0; v < 3; ++v) {
      for (int c = 0; c < 3; ++c) {
        if (tolerance == 0) {
          ASSERT_EQ(va[v][c], vb[v][c]) << what << ": face " << f;
        } else {
          ASSERT_NEAR(va[v][c], vb[v][c], tolerance) << what << ": face " << f;
        }
      }
    }
  }
  ASSERT_EQ(a.patches.size(), b.patches.size()) << what;
}

TEST_F(AnyScale, PowerOfTwoScalesGiveBitIdenticalNormalisedFaces) {
  for (int face_target : {0, 40}) {
    const Scene unit = prepared(1.0, face_target);
    for (int exponent : {600, 1000, -1000}) {
      const Scene s = prepared(std::ldexp(1.0, exponent), face_target);
      expect_faces_within(s, unit, 0, "2^" + std::to_string(exponent) + ", --faces " + std::to_string(face_target));
      EXPECT_EQ(s.camera.position, unit.camera.position);
      EXPECT_EQ(s.camera.look_at, unit.camera.look_at);
      // world = offset + p / scale still holds.
      EXPECT_EQ(s.normalisation.scale, std::ldexp(unit.normalisation.scale, -exponent));
    }
  }
}

// 8 units in the last place of 1: each coordinate is rounded once when written at 1e200 or 1e-300,
// and the normalisation's difference, division and scaling each round once more.
TEST_F(AnyScale, HugeAndTinyScenesNormaliseAsAtUnitSize) {
  const double tolerance = 8 * DBL_EPSILON;
  for (int face_target : {0, 40}) {
    const Scene unit = prepared(1.0, face_target);
    for (double k : {1e200, 1e-300, 1e300, 1e-307}) {
      const Scene s = prepared(k, face_target);
      expect_faces_within(s, unit, tolerance, std::to_string(k));
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(s.camera.position[c], unit.camera.position[c], 8 * tolerance);
      }
      EXPECT_NEAR(s.normalisation.scale * k / unit.normalisation.scale, 1.0, tolerance);
    }
  }
}

TEST_F(AnyScale, ScenesBelowTheNormalDoublesAreRefused) {
  try {
    prepared(1e-309);  // extent 2e-309: subnormal coordinates
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("smaller than the smallest normal double"), std::string::npos) << e.what();
  }
}

TEST(AnyScaleText, CoordinatesThatAreNotFiniteAreRefusedWithFileAndLine) {
  const std::string material = "material w reflectance 0.5 0.5 0.5 emission 1 1 1\n";
  for (const char* bad : {"1e999", "inf", "nan", "-1e400"}) {
    try {
      parse_scene_text(material + "tri a w 0 0 0 1 0 0 0 " + bad + " 0\n", "big.scene");
      FAIL() << bad;
    } catch (const SceneFileError& e) {
      EXPECT_EQ(std::string(e.what()), std::string("big.scene:2: '") + bad + "' is not a finite number (vertex coordinate)");
    }
  }
}

TEST(AnyScaleText, NormaliseRefusesFacesThatAreNotFinite) {
  Scene s;
  s.name = "handmade";
  s.faces.push_back({{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}});
  s.faces.push_back({{{0, 0, 0}, {1, 0, 0}, {0, 0, NAN}}});
  try {
    normalise(s);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "scene 'handmade': face 1 has a coordinate that is not finite");
  }
}

// Parts whose sizes differ by more than doubles hold: the room's faces have no area once the scene
// is scaled to the unit cube. It used to end in "scene emits no light" (the lamp had vanished).
TEST(AnyScaleText, PartsTooFarApartForTheDoublesAreNamed) {
  Scene s;
  s.name = "far";
  s.faces.push_back({{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}});
  s.faces.push_back({{{1e300, 0, 0}, {2e300, 0, 0}, {1e300, 1e300, 0}}});
  try {
    normalise(s);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "scene 'far': 1 of 2 faces (the first: face 0) have no area once the scene is scaled into "
                           "the unit cube: its parts differ in size by more than double precision holds; bring them "
                           "closer together");
  }
}

}  // namespace
}  // namespace rc
