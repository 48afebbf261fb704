// Bad scene input ends in a clear error, quickly: devices and endless streams, numbers with
// trailing text, folded quads, and scenes that would grow past kMaxFaces or kMaxPatches.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "scenes/composition.h"
#include "scenes/mesh_import.h"
#include "scenes/prepare.h"
#include "scenes/scene_builder.h"
#include "scenes/scene_file.h"

namespace rc {
namespace {

std::string prepare_error(const SceneOptions& o) {
  try {
    prepare_scene(o);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

std::string parse_error(const std::string& text) {
  try {
    parse_scene_text(text, "s.scene");
  } catch (const SceneFileError& e) {
    return e.what();
  }
  return "";
}

const std::string kMaterial = "material w reflectance 0.5 0.5 0.5 emission 1 1 1\n";

// --scene /dev/zero used to read forever (no line break for the format sniffing to stop at).
TEST(BoundedInput, AnEndlessDeviceIsRefusedAtOnce) {
  const auto start = std::chrono::steady_clock::now();
  SceneOptions o;
  o.file = "/dev/zero";
  EXPECT_EQ(prepare_error(o), "/dev/zero: is a character device, not a regular file (a scene file must be one)");
  EXPECT_FALSE(is_text_scene_file("/dev/zero"));
  EXPECT_FALSE(is_composition_file("/dev/zero"));
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
}

TEST(BoundedInput, EmptyAndCommentOnlyFilesSayTheyHaveNoFaces) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("rc_bounded_empty_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  for (const char* text : {"", "# only a comment\n\n   \n"}) {
    const std::string path = (dir / "x.scene").string();
    std::ofstream(path) << text;
    SceneOptions o;
    o.file = path;
    EXPECT_EQ(prepare_error(o), path + ": scene '" + path + "' has no faces");
  }
  std::filesystem::remove_all(dir);
}

TEST(BoundedInput, ADirectoryIsNamed) {
  SceneOptions o;
  o.file = "/tmp";
  EXPECT_EQ(prepare_error(o), "/tmp: is a directory, not a file");
  try {
    load_scene_file("/tmp");
    FAIL();
  } catch (const SceneFileError& e) {
    EXPECT_STREQ(e.what(), "/tmp: is a directory, not a file");
  }
}

// std::stod read a prefix; the whole word must be the number now.
TEST(BoundedInput, NumbersMustBeWholeAndFinite) {
  EXPECT_EQ(parse_error(kMaterial + "tri a w 0 0 0 1.5x 0 0 0 1 0\n"), "s.scene:2: '1.5x' is not a finite number (vertex coordinate)");
  EXPECT_EQ(parse_error("material w reflectance 0.5 0.5 0.5x\n"), "s.scene:1: '0.5x' is not a finite number (reflectance value)");
  EXPECT_EQ(parse_error("material w reflectance 0.5 0.5 0.5 emission 1 1e999 1\n"),
            "s.scene:1: '1e999' is not a finite number (emission value)");
  EXPECT_EQ(parse_error(kMaterial + "tri a w 0 0 0 1 0 0 0 1 0\ncamera 1 1 -3 1 1 0 0 1 0 45deg\n"),
            "s.scene:3: '45deg' is not a finite number (vertical field of view (degrees))");
  EXPECT_EQ(parse_error(kMaterial + "tri a w 0 0 0 1 0 0 0 1 0\n"), "");
}

TEST(BoundedInput, AMeshCoordinateThatIsNotFiniteIsNamed) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("rc_bounded_inf_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "inf.obj").string();
  std::ofstream(path) << "v 0 0 0\nv 1 0 0\nv 0 1e999 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\n";
  try {
    import_mesh_file(path);
    FAIL() << "no error";
  } catch (const SceneFileError& e) {
    EXPECT_NE(std::string(e.what()).find(path + ": mesh 0"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("has a coordinate that is not finite"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(dir);
}

TEST(BoundedInput, AMeshEmissionThatIsNotFiniteIsNamed) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("rc_bounded_hot_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "hot.mtl") << "newmtl hot\nKd 0.5 0.5 0.5\nKe 1e999 1 1\n";
  const std::string path = (dir / "hot.obj").string();
  std::ofstream(path) << "mtllib hot.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl hot\nf 1 2 3\n";
  try {
    import_mesh_file(path);
    FAIL() << "no error";
  } catch (const SceneFileError& e) {
    EXPECT_EQ(std::string(e.what()), path + ": material 'hot #1': emissive colour (inf, 1, 1): an emission must be "
                                            "finite and not negative (docs/scenes.md, Meshes)");
  }
  std::filesystem::remove_all(dir);
}

TEST(FoldedQuad, IsRefusedNamingFileLineSurfaceAndAngle) {
  // v3 lifted 0.3 above the floor's plane, over v1's side: the halves face each other.
  EXPECT_EQ(parse_error(kMaterial + "quad fold w 0 0 0  0 0 1  1 0 1  0 0.3 1\n"),
            "s.scene:2: quad 'fold' is not planar: its triangles v0 v1 v2 and v0 v2 v3 are folded by 157 degrees "
            "along v0-v2 (at most 5 allowed). Fix the vertices (their order: a bow tie folds by 180), or write the "
            "fold as two 'tri' lines if it is meant");
  // A bow tie: v2 and v3 swapped.
  EXPECT_NE(parse_error(kMaterial + "quad tie w 0 0 0  1 0 0  0 0 1  1 0 1\n").find("folded by 180 degrees"), std::string::npos);
}

TEST(FoldedQuad, SmallFoldsPassAsTheCornellRedWallDoes) {
  // Folded by 4 and 6 degrees: v3 = (0, 1, 0) rotated about the v0-v2 diagonal of the unit square.
  auto quad_folded_by = [&](double degrees) {
    const double t = degrees * M_PI / 180, h = std::sqrt(0.5);
    const Vec3 mid(0.5, 0.5, 0), out = Vec3(-1, 1, 0) / std::sqrt(2.0);
    const Vec3 v3 = mid + h * (std::cos(t) * out + std::sin(t) * Vec3(0, 0, 1));
    char line[256];
    std::snprintf(line, sizeof line, "quad q w 0 0 0  1 0 0  1 1 0  %.17g %.17g %.17g\n", v3.x, v3.y, v3.z);
    return parse_error(kMaterial + line);
  };
  EXPECT_EQ(quad_folded_by(4.0), "");
  EXPECT_NE(quad_folded_by(6.0).find("is not planar"), std::string::npos);
  // Planar to within the embedded box's red wall (0.47 degrees): every surface of it loads.
  EXPECT_NO_THROW(prepare_scene(SceneOptions{}));
}

TEST(FoldedQuad, AComposedLightIsCheckedToo) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("rc_bounded_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "light.json").string();
  std::ofstream(path) << R"({"schema": "rc2000sim.composition/1", "light": {"corners": [[0, 500, 0], [0, 500, 100], [100, 500, 100], [0, 400, 100]], "emission": [1, 1, 1]}})";
  try {
    load_composition(path);
    FAIL() << "no error";
  } catch (const SceneFileError& e) {
    EXPECT_NE(std::string(e.what()).find(path + ": light.corners: quad 'light' is not planar"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(dir);
}

TEST(SceneLimits, TooManyFacesOrPatchesIsAnErrorBeforeAnythingIsBuilt) {
  const auto start = std::chrono::steady_clock::now();
  SceneOptions o;
  o.face_target = static_cast<int>(kMaxFaces) + 1;
  EXPECT_EQ(prepare_error(o), "--faces asks for 4194305 faces, more than the limit of 4194304 (kMaxFaces, set by the "
                              "memory a solve needs; docs/scenes.md, Limits)");
  o = SceneOptions{};
  o.face_levels = 8;
  o.patch_levels = 2;
  EXPECT_EQ(prepare_error(o), "--patch-levels 2 makes 39845888 patches, more than the limit of 16777216 (kMaxPatches, "
                              "set by the memory a solve needs; docs/scenes.md, Limits)");
  o = SceneOptions{};
  o.face_target = 300000;
  o.face_levels = 2;
  EXPECT_NE(prepare_error(o).find("--face-levels 2 makes 4800000 faces, more than the limit of 4194304"), std::string::npos);
  o = SceneOptions{};
  o.face_levels = 3;
  o.patch_size = 0.001;
  EXPECT_NE(prepare_error(o).find("--patch-size 0.001 makes "), std::string::npos);
  EXPECT_NE(prepare_error(o).find(" patches, more than the limit of 16777216 (kMaxPatches"), std::string::npos);
  // Patches smaller than 8 levels of splitting reach are refused, not silently made larger.
  o = SceneOptions{};
  o.face_target = 1000;
  o.patch_size = 1e-6;
  EXPECT_NE(prepare_error(o).find("--patch-size 1e-06: face 0: patches of at most 1e-06 need more than 8 levels of "
                                  "splitting of a face whose longest edge is "),
            std::string::npos)
      << prepare_error(o);
  EXPECT_NE(prepare_error(o).find("refine the faces first (--faces, --face-levels) or ask for larger patches"),
            std::string::npos);
  o = SceneOptions{};
  o.face_target = -5;
  EXPECT_EQ(prepare_error(o), "--faces must not be negative, got -5");
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(30));
}

}  // namespace
}  // namespace rc
