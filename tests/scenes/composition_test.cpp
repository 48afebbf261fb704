// Composed scenes (scenes/composition.h): the Cornell Box plus a mesh placed in it, material
// overrides, an added light, and errors that name the file and the key.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "scenes/composition.h"
#include "scenes/cornell_box.h"
#include "scenes/prepare.h"

namespace rc {
namespace {

class CompositionTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() / ("rc_composition_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
    // A unit tetrahedron as an OBJ of our own (no test data needed).
    std::ofstream(dir_ / "tetra.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
    return (dir_ / name).string();
  }
  std::string error_of(const std::string& text) {
    const std::string path = write("bad.json", text);
    try {
      load_composition(path);
    } catch (const SceneFileError& e) {
      return e.what();
    }
    return "";
  }

  std::filesystem::path dir_;
};

// "two_sided": a back face for each of the tetrahedron's 4, each pair one sheet once prepared. (It
// floats above the floor: resting on it, its bottom would face the floor back to back, and the floor
// would join that sheet, as it should.)
TEST_F(CompositionTest, ATwoSidedMeshGetsABackForEveryFace) {
  const std::string path = write("scene.json", R"({"schema": "rc2000sim.composition/1", "room": "cornell-box",
    "meshes": [{"file": "tetra.obj", "fit_into": {"min": [100, 50, 100], "max": [300, 150, 300]}, "two_sided": true}]})");
  const LoadedScene s = load_composition(path);
  const std::size_t box = cornell_box().faces.size();
  ASSERT_EQ(s.scene.faces.size(), box + 8);
  for (std::size_t f = 0; f < 4; ++f) {
    const Face& front = s.scene.faces[box + f];
    const Face& back = s.scene.faces[box + 4 + f];
    EXPECT_EQ(back.tri.cross(), -front.tri.cross());
    EXPECT_EQ(s.scene.surface_name(back.surface), s.scene.surface_name(front.surface) + " (back)");
  }
  SceneOptions o;
  o.file = path;
  o.patch_levels = 0;
  const Scene prepared = prepare_scene(o).scene;
  EXPECT_EQ(prepared.sheets.shared_sheets(), 4u);
  EXPECT_EQ(prepared.sheets.faces_in_shared_sheets(), 8u);
  EXPECT_EQ(error_of(R"({"schema": "rc2000sim.composition/1", "meshes": [{"file": "tetra.obj", "two_sided": 1}]})"),
            (dir_ / "bad.json").string() + ": meshes[0].two_sided: must be true or false");
}

// The box's 38 faces plus the tetrahedron's 4, fitted into the given box (uniform scale, centred
// on x and z, resting on its floor), with its material replaced by the override.
TEST_F(CompositionTest, AMeshFitsIntoTheBoxWithItsMaterial) {
  const std::string path = write("scene.json", R"({"schema": "rc2000sim.composition/1", "room": "cornell-box",
    "meshes": [{"file": "tetra.obj", "fit_into": {"min": [100, 0, 100], "max": [300, 100, 300]},
                "material": {"reflectance": [0.2, 0.7, 0.3]}}]})");
  ASSERT_TRUE(is_composition_file(path));
  const LoadedScene s = load_composition(path);
  const Scene box = cornell_box();
  ASSERT_EQ(s.scene.faces.size(), box.faces.size() + 4);
  Vec3 lo{1e300}, hi{-1e300};
  for (std::size_t f = box.faces.size(); f < s.scene.faces.size(); ++f) {
    const Face& face = s.scene.faces[f];
    EXPECT_DOUBLE_EQ(s.scene.materials[face.material].reflectance.band[1], 0.7);
    for (const Vec3& v : {face.tri.v0, face.tri.v1, face.tri.v2}) {
      lo = glm::min(lo, v);
      hi = glm::max(hi, v);
    }
  }
  // A unit tetrahedron scaled by min(200, 100, 200) = 100: 100 high, 100 wide, centred at 200.
  EXPECT_NEAR(lo.y, 0, 1e-9);
  EXPECT_NEAR(hi.y, 100, 1e-9);
  EXPECT_NEAR((lo.x + hi.x) / 2, 200, 1e-9);
  EXPECT_NEAR((lo.z + hi.z) / 2, 200, 1e-9);
  EXPECT_NEAR(hi.x - lo.x, 100, 1e-9);
  // The box's own faces and materials are unchanged.
  EXPECT_EQ(s.scene.faces[0].tri.v0, box.faces[0].tri.v0);
  EXPECT_EQ(s.scene.materials[0].name, box.materials[0].name);
}

// Rotate, scale and translate: a half-turn about y keeps the centre and mirrors x and z.
TEST_F(CompositionTest, RotateScaleTranslate) {
  const std::string path = write("scene.json", R"({"schema": "rc2000sim.composition/1",
    "meshes": [{"file": "tetra.obj", "rotate": {"axis": [0, 1, 0], "degrees": 180}, "scale": 10,
                "translate": [200, 50, 200]}]})");
  const LoadedScene s = load_composition(path);
  const Face& first = s.scene.faces[cornell_box().faces.size()];
  // Vertex (0,0,0) of a tetrahedron centred at (0.5,0.5,0.5): turned to (1,0,1) - centre, times 10,
  // plus centre + translate.
  EXPECT_NEAR(first.tri.v0.x, 5 + 0.5 + 200, 1e-9);
  EXPECT_NEAR(first.tri.v0.y, -5 + 0.5 + 50, 1e-9);
  EXPECT_NEAR(first.tri.v0.z, 5 + 0.5 + 200, 1e-9);
}

// A room without light gets one from the description; a composition goes through scene
// preparation like any scene.
TEST_F(CompositionTest, AnAddedLightLightsAMeshRoom) {
  std::ofstream(dir_ / "room.obj") << "v 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nv 0 1 0\nv 1 1 0\nv 1 1 1\nv 0 1 1\n"
                                      "f 4 3 2 1\nf 6 7 8 5\nf 2 6 5 1\nf 3 7 6 2\nf 4 8 7 3\nf 1 5 8 4\n";
  const std::string path = write("scene.json", R"({"schema": "rc2000sim.composition/1", "room": {"file": "room.obj"},
    "light": {"corners": [[0.4, 0.99, 0.4], [0.6, 0.99, 0.4], [0.6, 0.99, 0.6], [0.4, 0.99, 0.6]],
              "emission": [5, 5, 5]}})");
  SceneOptions options;
  options.file = path;
  options.patch_levels = 1;
  const PreparedScene p = prepare_scene(options);
  EXPECT_EQ(p.scene.faces.size(), 14u);
  EXPECT_EQ(p.scene.materials.back().emission.band[0], 5.0);
  // The light faces down, into the room.
  EXPECT_LT(p.scene.faces.back().tri.normal().y, 0);
}

// A room of its own units with no camera is framed (prepare_scene: frame_bounds), so the picture sees
// it; a composition's `camera` key sets the camera, and a bad one is refused naming the key.
TEST_F(CompositionTest, AMeshRoomIsFramedUnlessACameraIsGiven) {
  std::ofstream(dir_ / "room.obj") << "v 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nv 0 1 0\nv 1 1 0\nv 1 1 1\nv 0 1 1\n"
                                      "f 4 3 2 1\nf 6 7 8 5\nf 2 6 5 1\nf 3 7 6 2\nf 4 8 7 3\nf 1 5 8 4\n";
  const std::string light = R"("light": {"corners": [[0.4, 0.99, 0.4], [0.6, 0.99, 0.4], [0.6, 0.99, 0.6], [0.4, 0.99, 0.6]],
              "emission": [5, 5, 5]})";
  SceneOptions options;
  options.patch_levels = 0;
  options.file = write("framed.json", R"({"schema": "rc2000sim.composition/1", "room": {"file": "room.obj"}, )" + light + "}");
  const Scene framed = prepare_scene(options).scene;
  EXPECT_FALSE(framed.camera_given);
  // The normalised room fills [0, 1)^3 about; the framing camera looks at its centre along +z.
  EXPECT_NEAR(framed.camera.look_at.x, 0.5, 0.01);
  EXPECT_NEAR(framed.camera.look_at.y, 0.5, 0.01);
  EXPECT_LT(framed.camera.position.z, 0);
  options.file = write("given.json", R"({"schema": "rc2000sim.composition/1", "room": {"file": "room.obj"}, )" + light +
                                         R"(, "camera": {"position": [0.5, 0.5, 0.1], "look_at": [0.5, 0.5, 1], "fov_deg": 70}})");
  const Scene given = prepare_scene(options).scene;
  EXPECT_TRUE(given.camera_given);
  EXPECT_EQ(given.camera.vertical_fov_deg, 70);
  EXPECT_NEAR(given.camera.position.z, 0.1, 0.01);  // normalised with the room (same units as its corners)
  // The Cornell room keeps the Cornell camera.
  options.file = write("cornell.json", R"({"schema": "rc2000sim.composition/1", "room": "cornell-box"})");
  EXPECT_TRUE(prepare_scene(options).scene.camera_given);
  const std::string bad = (dir_ / "bad.json").string();
  EXPECT_EQ(error_of(R"({"schema": "rc2000sim.composition/1", "camera": {"position": [0, 0, 0]}})"),
            bad + ": camera: needs position and look_at");
  EXPECT_EQ(error_of(R"({"schema": "rc2000sim.composition/1", "camera": {"position": [0, 0, 0], "look_at": [1, 1, 1], "zoom": 2}})"),
            bad + ": camera.zoom: unknown key (allowed: position, look_at, up, fov_deg)");
  EXPECT_NE(error_of(R"({"schema": "rc2000sim.composition/1", "camera": {"position": [1, 1, 1], "look_at": [1, 1, 1]}})")
                .find(bad + ": camera: "), std::string::npos);
}

TEST_F(CompositionTest, ErrorsNameTheFileAndTheKey) {
  const std::string bad = (dir_ / "bad.json").string();
  EXPECT_EQ(error_of(R"({"schema": "rc2000sim.composition/1", "meshes": [{"file": "tetra.obj", "sclae": 2}]})"),
            bad + ": meshes[0].sclae: unknown key (allowed: file, rotate, fit_into, scale, translate, material, two_sided)");
  EXPECT_EQ(error_of(R"({"schema": "rc2000sim.composition/1", "meshes": [{"file": "tetra.obj", "scale": -1}]})"),
            bad + ": meshes[0].scale: must be positive");
  EXPECT_EQ(error_of(R"({"schema": "rc2000sim.composition/1", "meshes": [{"file": "tetra.obj",
            "material": {"reflectance": [1.2, 0, 0]}}]})"),
            bad + ": meshes[0].material.reflectance: components must be at least 0 and below 1.000000");
  EXPECT_EQ(error_of(R"({"schema": "rc2000sim.composition/1", "room": {"file": "missing.obj"}})"),
            (dir_ / "missing.obj").string() + ": cannot open (No such file or directory)");
  EXPECT_EQ(error_of(R"({"schema": "rc2000sim.composition/1", "meshes": [{"file": "tetra.obj", "scale": 2,
            "fit_into": {"min": [0, 0, 0], "max": [1, 1, 1]}}]})"),
            bad + ": meshes[0].fit_into: excludes scale and translate");
  EXPECT_NE(error_of("{not json").find(bad + ": line 1, column 3: not valid JSON"), std::string::npos);
  EXPECT_FALSE(is_composition_file(write("other.json", R"({"schema": "something else"})")));
  // A schema of another type is not this format (value() would throw a type_error on it).
  EXPECT_EQ(error_of(R"({"schema": 1, "room": "cornell-box"})"),
            bad + ": schema: must be \"rc2000sim.composition/1\"");
  EXPECT_FALSE(is_composition_file(write("number.json", R"({"schema": 1})")));
}

// Our own formats named where a mesh is expected: said so, not Assimp's "No suitable reader found".
TEST_F(CompositionTest, CompositionsDoNotNestAndTextScenesAreNotMeshes) {
  const std::string inner = write("inner.json", R"({"schema": "rc2000sim.composition/1", "room": "cornell-box"})");
  write("lamp.scene", "material l reflectance 0.5 0.5 0.5 emission 1 1 1\ntri t l 0 0 0 1 0 0 0 1 0\n");
  const std::string bad = (dir_ / "bad.json").string();
  EXPECT_EQ(error_of(R"({"schema": "rc2000sim.composition/1", "meshes": [{"file": "inner.json"}]})"),
            bad + ": meshes[0].file: " + inner + " is a composition; compositions do not nest (name its meshes here)");
  EXPECT_EQ(error_of(R"({"schema": "rc2000sim.composition/1", "room": {"file": "inner.json"}})"),
            bad + ": room.file: " + inner + " is a composition; compositions do not nest (name its room or meshes here)");
  EXPECT_EQ(error_of(R"({"schema": "rc2000sim.composition/1", "meshes": [{"file": "lamp.scene"}]})"),
            bad + ": meshes[0].file: " + (dir_ / "lamp.scene").string() +
                " is a text scene; a mesh must be a mesh file (OBJ, PLY, OFF, STL, ...), or use it as the room");
  EXPECT_EQ(load_composition(write("room.json", R"({"schema": "rc2000sim.composition/1", "room": {"file": "lamp.scene"}})"))
                .scene.faces.size(),
            1u);
}

// Editors that save with a UTF-8 byte order mark: the file is still recognised and read.
TEST_F(CompositionTest, AByteOrderMarkIsSkipped) {
  const std::string path = write("bom.json", std::string("\xEF\xBB\xBF") +
                                                 R"({"schema": "rc2000sim.composition/1", "room": "cornell-box"})");
  ASSERT_TRUE(is_composition_file(path));
  EXPECT_EQ(load_composition(path).scene.faces.size(), cornell_box().faces.size());
  EXPECT_FALSE(is_composition_file(write("short.json", "\xEF\xBB")));
}

}  // namespace
}  // namespace rc
