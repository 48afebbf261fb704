// Mesh materials checked like the text format's (docs/scenes.md, Meshes): reflectance finite and in
// [0, 1] (0.99 and above clamped with a warning), emission finite and not negative; an OBJ `usemtl`
// that no MTL defines warned once per name; names that are not UTF-8 kept with \xNN escapes.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "io/text_encoding.h"
#include "scenes/mesh_import.h"

namespace rc {
namespace {

namespace fs = std::filesystem;

class MeshMaterials : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("rc_mesh_materials_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // An OBJ of one triangle per `usemtl` line given, with `mtl` as its material file.
  std::string obj(const std::string& mtl, const std::string& uses) {
    std::ofstream(dir_ / "m.mtl", std::ios::binary) << mtl;
    std::ofstream(dir_ / "m.obj", std::ios::binary) << "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n" << uses;
    return (dir_ / "m.obj").string();
  }
  std::string error_of(const std::string& mtl) {
    const std::string path = obj(mtl, "usemtl a\nf 1 2 3\n");
    try {
      import_mesh_file(path, options());
    } catch (const SceneFileError& e) {
      return e.what();
    }
    return "";
  }
  static MeshImportOptions options() {
    MeshImportOptions o;
    o.require_emitter = false;
    return o;
  }

  fs::path dir_;
};

// Negative and NaN colours used to become 0 without a word; 1.5 was clamped to 0.99.
TEST_F(MeshMaterials, ColoursTheTextFormatRefusesAreRefusedNamingFileAndMaterial) {
  const std::string path = (dir_ / "m.obj").string();
  const std::string reflectance = "a reflectance must be finite and within [0, 1] (0.99 and above are clamped to 0.99) "
                                  "(docs/scenes.md, Meshes)";
  const std::string emission = "an emission must be finite and not negative (docs/scenes.md, Meshes)";
  EXPECT_EQ(error_of("newmtl a\nKd -0.5 0.5 0.5\n"), path + ": material 'a #1': diffuse colour (-0.5, 0.5, 0.5): " + reflectance);
  EXPECT_EQ(error_of("newmtl a\nKd 0.5 1.5 0.5\n"), path + ": material 'a #1': diffuse colour (0.5, 1.5, 0.5): " + reflectance);
  EXPECT_EQ(error_of("newmtl a\nKd 0.5 0.5 nan\n"), path + ": material 'a #1': diffuse colour (0.5, 0.5, nan): " + reflectance);
  EXPECT_EQ(error_of("newmtl a\nKd 0.5 0.5 0.5\nKe -1 1 1\n"), path + ": material 'a #1': emissive colour (-1, 1, 1): " + emission);
  EXPECT_EQ(error_of("newmtl a\nKd 0.5 0.5 0.5\nKe 1 nan 1\n"), path + ": material 'a #1': emissive colour (1, nan, 1): " + emission);
  EXPECT_EQ(error_of("newmtl a\nKd 0.5 0.5 0.5\nKe 1e999 1 1\n"), path + ": material 'a #1': emissive colour (inf, 1, 1): " + emission);
}

TEST_F(MeshMaterials, PureWhiteIsClampedWithAWarningAsDocumented) {
  const LoadedScene s = import_mesh_file(obj("newmtl a\nKd 1 0.995 0.5\nKe 2 2 2\n", "usemtl a\nf 1 2 3\n"), options());
  ASSERT_EQ(s.scene.materials.size(), 1u);
  EXPECT_EQ(s.scene.materials[0].reflectance.band[0], 0.99);
  EXPECT_EQ(s.scene.materials[0].reflectance.band[1], 0.99);
  EXPECT_EQ(s.scene.materials[0].reflectance.band[2], 0.5);
  EXPECT_EQ(s.scene.materials[0].emission.band[0], 2.0);
  std::size_t clamped = 0;
  for (const std::string& w : s.warnings) clamped += w.find("clamped to reflectance") != std::string::npos;
  EXPECT_EQ(clamped, 1u);
}

// Assimp gave an undefined material its default grey silently.
TEST_F(MeshMaterials, AnUndefinedUsemtlIsWarnedOncePerName) {
  const std::string path = obj("newmtl a\nKd 0.5 0.5 0.5\n",
                               "usemtl a\nf 1 2 3\nusemtl missing\nf 1 3 4\nusemtl a\nf 1 2 4\nusemtl missing\nf 2 3 4\n"
                               "usemtl other\nf 1 4 2\n");
  const LoadedScene s = import_mesh_file(path, options());
  std::vector<std::string> undefined;
  for (const std::string& w : s.warnings)
    if (w.find("is defined in no material file") != std::string::npos) undefined.push_back(w);
  ASSERT_EQ(undefined.size(), 2u);
  EXPECT_EQ(undefined[0], path + ":8: usemtl 'missing' is defined in no material file (mtllib m.mtl); Assimp gives its "
                                 "faces its default material");
  EXPECT_EQ(undefined[1].rfind(path + ":14: usemtl 'other' is", 0), 0u) << undefined[1];
}

// A Latin-1 MTL used to let the solve finish and then fail in report.json's writer (type_error.316).
TEST_F(MeshMaterials, ANameThatIsNotUtf8IsKeptEscaped) {
  const LoadedScene s = import_mesh_file(obj("newmtl caf\xE9\nKd 0.5 0.5 0.5\nKe 1 1 1\n", "usemtl caf\xE9\nf 1 2 3\n"), options());
  ASSERT_EQ(s.scene.materials.size(), 1u);
  EXPECT_EQ(s.scene.materials[0].name, "caf\\xE9 #1");
  for (const std::string& w : s.warnings) EXPECT_EQ(io::first_invalid_utf8(w), std::string::npos) << w;
}

}  // namespace
}  // namespace rc
