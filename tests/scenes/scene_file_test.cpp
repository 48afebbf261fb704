#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include "scenes/mesh_import.h"
#include "scenes/prepare.h"
#include "scenes/scene_file.h"

namespace rc {
namespace {

std::string error_of(const std::string& text) {
  try {
    parse_scene_text(text, "bad.scene");
  } catch (const SceneFileError& e) {
    return e.what();
  }
  return "no error";
}

const char* kMaterial = "material w reflectance 0.5 0.5 0.5 emission 1 1 1\n";

TEST(SceneFile, ExampleSceneLoads) {
  SceneOptions o;
  o.file = std::string(RC_SOURCE_DIR) + "/scenes/examples/two-rooms.scene";
  o.patch_levels = 1;
  const PreparedScene p = prepare_scene(o);
  EXPECT_EQ(p.scene.materials.size(), 3u);
  EXPECT_EQ(p.scene.faces.size(), 10u);  // 4 quads x 2 + 2 triangles
  EXPECT_EQ(p.scene.patches.size(), 40u);
  EXPECT_TRUE(p.warnings.empty());
  EXPECT_DOUBLE_EQ(p.scene.camera.vertical_fov_deg, 45.0);
}

TEST(SceneFile, ErrorsNameFileLineAndProblem) {
  EXPECT_EQ(error_of("# nothing\nbox 1 2 3\n"), "bad.scene:2: unknown keyword 'box' (expected material, quad, tri, two-sided or camera)");
  EXPECT_EQ(error_of(std::string(kMaterial) + "tri a w 0 0 0 1 0 0 0 1\n"), "bad.scene:2: missing vertex coordinate");
  EXPECT_EQ(error_of(std::string(kMaterial) + "tri a w 0 0 0 1 0 0 0 1 x\n"),
            "bad.scene:2: 'x' is not a finite number (vertex coordinate)");
  EXPECT_EQ(error_of("tri a nope 0 0 0 1 0 0 0 1 0\n"),
            "bad.scene:1: unknown material 'nope' (define it with 'material' first)");
  EXPECT_EQ(error_of(std::string(kMaterial) + "tri a w 0 0 0 1 0 0 0 1 0 7\n"), "bad.scene:2: unexpected '7' at end of line");
  EXPECT_EQ(error_of("material w emission 1 1 1\n"), "bad.scene:1: material 'w' needs 'reflectance r g b'");
  EXPECT_EQ(error_of(std::string(kMaterial) + kMaterial), "bad.scene:2: material 'w' is defined twice");
  EXPECT_NE(error_of("material w reflectance 1 0.5 0.5\n").find("bad.scene:1: material 'w': reflectance 1"),
            std::string::npos);
  EXPECT_EQ(error_of(kMaterial), "bad.scene: scene 'bad.scene' has no faces");
  EXPECT_EQ(error_of("camera 0 0 0 0 0 0 0 1 0 45\n"), "bad.scene:1: camera looks at its own position (0, 0, 0) (no view direction)");
}

TEST(SceneFile, ZeroAreaFacesAreDroppedAndReported) {
  const LoadedScene s = parse_scene_text(std::string(kMaterial) +
                                             "tri good w 0 0 0 1 0 0 0 1 0\n"
                                             "tri flat w 0 0 0 1 0 0 2 0 0\n"
                                             "quad half w 0 0 1 1 0 1 1 1 1 1 1 1\n",
                                         "d.scene");
  EXPECT_EQ(s.scene.faces.size(), 2u);  // good + the non-degenerate half of the quad
  ASSERT_EQ(s.warnings.size(), 2u);
  EXPECT_EQ(s.warnings[0], "d.scene:3: zero-area triangle of surface 'flat' dropped");
  EXPECT_EQ(s.warnings[1], "d.scene:4: zero-area triangle of surface 'half' dropped");
}

// Control bytes (here a NUL and an escape) are shown as \xNN, so the message is whole and readable.
TEST(SceneFile, ControlBytesInAMessageAreShownEscaped) {
  EXPECT_EQ(error_of(std::string("box\0x 1\n", 8)), "bad.scene:1: unknown keyword 'box\\x00x' (expected material, quad, tri, two-sided or camera)");
  EXPECT_EQ(error_of(std::string(kMaterial) + "tri a w 0 0 0 1 0 0 0 1 \x1b[31m\n"),
            "bad.scene:2: '\\x1B[31m' is not a finite number (vertex coordinate)");
}

// A second camera line would silently replace the first.
TEST(SceneFile, ASecondCameraIsAnError) {
  const std::string camera = "camera 1 1 -3 1 1 0 0 1 0 45\n";
  EXPECT_EQ(error_of(std::string(kMaterial) + "tri a w 0 0 0 1 0 0 0 1 0\n" + camera + camera),
            "bad.scene:4: a second camera (the first is on line 3); a scene has one");
}

// Editors that save with a UTF-8 byte order mark: the file is still a text scene, read as without it.
TEST(SceneFile, AByteOrderMarkIsSkipped) {
  const std::string text = std::string(kMaterial) + "tri a w 0 0 0 1 0 0 0 1 0\n";
  const std::string path = ::testing::TempDir() + "bom.scene";
  std::ofstream(path, std::ios::binary) << "\xEF\xBB\xBF" << text;
  ASSERT_TRUE(is_text_scene_file(path));
  SceneOptions o;
  o.file = path;
  o.patch_levels = 0;
  EXPECT_EQ(prepare_scene(o).scene.faces.size(), 1u);
  EXPECT_EQ(parse_scene_text("\xEF\xBB\xBF" + text, "b.scene").scene.faces.size(), 1u);
  std::remove(path.c_str());
}

TEST(SceneFile, MissingFileIsAClearError) {
  EXPECT_THROW(load_scene_file("/nonexistent/x.scene"), SceneFileError);
  try {
    load_scene_file("/nonexistent/x.scene");
  } catch (const SceneFileError& e) {
    EXPECT_STREQ(e.what(), "/nonexistent/x.scene: cannot open (No such file or directory)");
  }
}

}  // namespace
}  // namespace rc
