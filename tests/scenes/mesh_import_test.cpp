// Meshes made by other tools, through Assimp (scenes/mesh_import.h): real models from Debian's
// assimp-testmodels (installed by scripts/test; test data only) in several formats, text and binary,
// recognised by content; the malformed files that package ships give clear errors, no crash.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "scenes/mesh_import.h"
#include "scenes/normalise.h"
#include "scenes/prepare.h"

namespace rc {
namespace {

const std::string kModels = "/usr/share/assimp/models";

#define REQUIRE_TESTMODELS()                                                                     \
  if (!std::filesystem::exists(kModels)) GTEST_SKIP() << kModels << " is missing: install assimp-testmodels " \
                                                                    "(scripts/test does)"

LoadedScene import(const std::string& relative) {
  MeshImportOptions o;
  o.require_emitter = false;  // a lone model emits nothing; tests look at its geometry and materials
  return import_mesh_file(kModels + "/" + relative, o);
}

std::string error_of(const std::string& path, const MeshImportOptions& o = {}) {
  try {
    import_mesh_file(path, o);
  } catch (const SceneFileError& e) {
    return e.what();
  }
  return "";
}

// Triangulated face counts of real models in five formats (two binary), and the box's bounds after
// normalisation into [0, 1)^3: a cube stays a cube, centred, as large as it fits.
TEST(MeshImport, RealModelsInSeveralFormats) {
  REQUIRE_TESTMODELS();
  struct Case {
    const char* file;
    std::size_t faces;
  } cases[] = {{"OBJ/box.obj", 12},
               {"PLY/cube_binary.ply", 12},
               {"STL/Spider_binary.stl", 1312},
               {"STL/Spider_ascii.stl", 1312},
               {"glTF2/BoxTextured-glTF-Binary/BoxTextured.glb", 12},
               {"OFF/Cube.off", 12},
               {"Collada/duck.dae", 4212},
               {"3DS/fels.3ds", 768}};
  for (const Case& c : cases) {
    const LoadedScene l = import(c.file);
    EXPECT_EQ(l.scene.faces.size(), c.faces) << c.file;
    EXPECT_FALSE(l.scene.materials.empty()) << c.file;
  }
  Scene box = import("OBJ/box.obj").scene;
  normalise(box);
  Vec3 lo{1, 1, 1}, hi{0, 0, 0};
  for (const Triangle& t : box.face_triangles()) {
    for (const Vec3& v : {t.v0, t.v1, t.v2}) {
      lo = {std::min(lo.x, v.x), std::min(lo.y, v.y), std::min(lo.z, v.z)};
      hi = {std::max(hi.x, v.x), std::max(hi.y, v.y), std::max(hi.z, v.z)};
    }
  }
  EXPECT_GE(lo.x, 0.0);
  EXPECT_LT(hi.x, 1.0);
  EXPECT_NEAR(hi.x - lo.x, hi.y - lo.y, 1e-9);  // a cube: every side scaled alike
  EXPECT_NEAR(hi.y - lo.y, hi.z - lo.z, 1e-9);
  EXPECT_GT(hi.x - lo.x, 0.9);
}

// Materials: the OBJ's diffuse colour is the reflectance; pure white is clamped below 1 with a
// warning naming the material; a material without colour gets the documented default.
TEST(MeshImport, MaterialsBecomeReflectanceAndEmission) {
  REQUIRE_TESTMODELS();
  const LoadedScene box = import("OBJ/box.obj");  // its MTL-less default: Assimp's 0.6 grey
  EXPECT_DOUBLE_EQ(box.scene.materials[0].reflectance.band[0], 0.6f);
  const LoadedScene ply = import("PLY/cube_binary.ply");  // white
  EXPECT_DOUBLE_EQ(ply.scene.materials[0].reflectance.band[0], MeshImportOptions{}.max_reflectance);
  ASSERT_FALSE(ply.warnings.empty());
  EXPECT_NE(ply.warnings[0].find("clamped"), std::string::npos) << ply.warnings[0];
}

// Files that the package ships broken: each is an error naming the file, never a crash. One of them
// asks for hundreds of gigabytes; the import's memory cap turns that into an error too.
TEST(MeshImport, MalformedFilesGiveClearErrors) {
  REQUIRE_TESTMODELS();
  for (const char* file : {"invalid/malformed.obj", "invalid/empty.obj", "invalid/empty.ply", "invalid/empty.3ds",
                           "invalid/empty.off", "invalid/OutOfMemory.off", "OBJ/point_cloud.obj"}) {
    const std::string path = kModels + "/" + file;
    const std::string e = error_of(path);
    EXPECT_EQ(e.rfind(path + ": ", 0), 0u) << file << ": " << e;
  }
  EXPECT_NE(error_of(kModels + "/invalid/OutOfMemory.off").find("memory"), std::string::npos);
  EXPECT_EQ(error_of("/no/such/mesh.obj"), "/no/such/mesh.obj: cannot open (No such file or directory)");
}

// Broken files of our own that crashed or hung Assimp (fuzz/regressions/mesh): a face index past
// the vertices, a face list shorter than its count, a PLY header that never ends. Each is an error
// naming the file.
TEST(MeshImport, BrokenFacesAndHeadersGiveClearErrors) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "rc_mesh_import_broken";
  std::filesystem::create_directories(dir);
  const std::string kPlyHead = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                               "property float z\nelement face 1\nproperty list uchar int vertex_indices\n";
  const std::pair<const char*, std::string> files[] = {
      {"short.off", "OFF\n5 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 2 1\n"},   // aborted in Triangulate
      {"short-quad.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n4 0 1 2 3\n3 0 1 9\n"},
      {"index.ply", kPlyHead + "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 9\n"},   // read past the vertices
      {"far-index.ply", kPlyHead + "end_header\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2 900000\n"},  // crashed
      {"endless.ply", kPlyHead + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"}};
  MeshImportOptions o;
  o.require_emitter = false;
  for (const auto& [name, text] : files) {
    const std::string path = (dir / name).string();
    std::ofstream(path) << text;
    const std::string e = error_of(path, o);
    EXPECT_EQ(e.rfind(path + ": ", 0), 0u) << name << ": " << e;
  }
  EXPECT_EQ(error_of((dir / "endless.ply").string(), o), (dir / "endless.ply").string() +
                                                              ": a PLY header without its end_header line");
  // A binary PLY with an unknown property type (found by fuzzing; the harness's first byte picks
  // the extension): an assertion in Assimp ends the reader's process, and the import says so.
  std::ifstream found(std::string(RC_SOURCE_DIR) + "/fuzz/regressions/mesh/ply-unknown-property-type-aborts-in-assimp.ply",
                      std::ios::binary);
  found.get();
  const std::string aborts = (dir / "aborts.ply").string();
  std::ofstream(aborts, std::ios::binary) << found.rdbuf();
  EXPECT_EQ(error_of(aborts, o), aborts + ": the mesh reader (Assimp) failed on it: killed by signal 6 (Aborted) (a "
                                          "malformed file, or one that needs more than 8 GiB of memory)");
  std::filesystem::remove_all(dir);
}

// Issue 39: a GLB whose chunk length points past the file was answered by Assimp's "No suitable
// reader found" after 9 s. Its framing is checked first, whatever the extension, naming the problem.
TEST(MeshImport, BinaryGltfFramingIsCheckedBeforeAssimp) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "rc_mesh_import_glb";
  std::filesystem::create_directories(dir);
  const auto u32 = [](std::uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
  const std::string json = "{\"asset\":{\"version\":\"2.0\"}}     ";  // 32 bytes
  const auto glb = [&](std::uint32_t version, std::int64_t length_delta, std::uint32_t chunk_length, const std::string& type) {
    const std::string body = u32(chunk_length) + type + json;
    return "glTF" + u32(version) + u32(static_cast<std::uint32_t>(12 + body.size() + length_delta)) + body;
  };
  const std::pair<std::string, std::string> cases[] = {
      {glb(2, 0, 999999, "JSON"), "chunk 0 giving its length as 999999 bytes where 32 remain"},
      {glb(2, 5, 32, "JSON"), "a header that gives its length as 57 bytes where the file has 52"},
      {glb(3, 0, 32, "JSON"), "version 3 (1 and 2 exist)"},
      {glb(2, 0, 32, std::string("BIN\0", 4)), "a first chunk that is not JSON"},
      {"glTF" + u32(2), "no total length: the file ends at byte 8"},
  };
  MeshImportOptions o;
  o.require_emitter = false;
  for (const std::string extension : {".glb", ".bin"}) {
    for (const auto& [bytes, why] : cases) {
      const std::string path = (dir / ("bad" + extension)).string();
      std::ofstream(path, std::ios::binary) << bytes;
      EXPECT_EQ(error_of(path, o), path + ": a binary glTF (GLB) file with " + why + " (docs/scenes.md, Meshes)");
    }
  }
  std::filesystem::remove_all(dir);
}

// By content, not by name: the same OBJ and binary STL under meaningless extensions import alike,
// and rc2000sim's own scene text is recognised by its keywords.
TEST(MeshImport, FormatsAreRecognisedByContent) {
  REQUIRE_TESTMODELS();
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "rc_mesh_import_test";
  std::filesystem::create_directories(dir);
  std::filesystem::copy_file(kModels + "/OBJ/box.obj", dir / "box.data", std::filesystem::copy_options::overwrite_existing);
  std::filesystem::copy_file(kModels + "/STL/Spider_binary.stl", dir / "spider.bin",
                             std::filesystem::copy_options::overwrite_existing);
  MeshImportOptions o;
  o.require_emitter = false;
  EXPECT_EQ(import_mesh_file((dir / "box.data").string(), o).scene.faces.size(), 12u);
  EXPECT_EQ(import_mesh_file((dir / "spider.bin").string(), o).scene.faces.size(), 1312u);
  std::ofstream(dir / "room.txt") << "# a comment\nmaterial white reflectance 0.5 0.5 0.5\n";
  EXPECT_TRUE(is_text_scene_file((dir / "room.txt").string()));
  EXPECT_FALSE(is_text_scene_file((dir / "box.data").string()));
  std::filesystem::remove_all(dir);
}

// A mesh with an emissive material runs through scene preparation like any scene: a lit room as an
// OBJ with its MTL (faces wound into the room), and a model without an emitter is refused.
TEST(MeshImport, AnEmissiveMeshIsASceneAndOneWithoutLightIsRefused) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "rc_mesh_import_room";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "room.mtl") << "newmtl white\nKd 0.8 0.8 0.8\nnewmtl light\nKd 0.5 0.5 0.5\nKe 10 10 10\n";
  std::ofstream(dir / "room.obj") << "mtllib room.mtl\n"
                                     "v 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nv 0 1 0\nv 1 1 0\nv 1 1 1\nv 0 1 1\n"
                                     "v 0.4 0.99 0.4\nv 0.6 0.99 0.4\nv 0.6 0.99 0.6\nv 0.4 0.99 0.6\n"
                                     "usemtl white\nf 4 3 2 1\nf 6 7 8 5\nf 2 6 5 1\nf 3 7 6 2\nf 4 8 7 3\nf 1 5 8 4\n"
                                     "usemtl light\nf 9 10 11 12\n";
  SceneOptions options;
  options.file = (dir / "room.obj").string();
  options.patch_levels = 1;
  const PreparedScene room = prepare_scene(options);
  EXPECT_EQ(room.scene.faces.size(), 14u);
  EXPECT_EQ(room.scene.materials.size(), 2u);
  double emitted = 0;
  for (const Material& m : room.scene.materials) emitted += m.emission.band[0];
  EXPECT_DOUBLE_EQ(emitted, 10.0);
  std::ofstream(dir / "dark.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  EXPECT_NE(error_of((dir / "dark.obj").string()).find("no material emits light"), std::string::npos);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace rc
