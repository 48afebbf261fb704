// Scene inputs read once and recognised by their whole content (scenes/scene_source.h): long comment
// headers, other encodings, JSON that is not a composition, special files and pipes; and mesh
// materials checked like the text format's (scenes/mesh_import.h).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include <sys/stat.h>
#include <unistd.h>

#include "scenes/composition.h"
#include "scenes/mesh_import.h"
#include "scenes/prepare.h"
#include "scenes/scene_source.h"
#include "tests/common/temp_folder.h"

namespace rc {
namespace {

namespace fs = std::filesystem;

const std::string kScene =
    "material w reflectance 0.5 0.5 0.5 emission 1 1 1\n"
    "quad floor w  0 0 0  0 0 1  1 0 1  1 0 0\n";

class SceneSourceTest : public ::rc::test::TempFolderTest {
 protected:
  SceneSourceTest() : TempFolderTest("rc_scene_source") {}
  static std::string prepare_error(const std::string& path) {
    SceneOptions o;
    o.file = path;
    try {
      prepare_scene(o);
    } catch (const std::exception& e) {
      return e.what();
    }
    return "";
  }
  static std::size_t faces_of(const std::string& path) {
    SceneOptions o;
    o.file = path;
    return prepare_scene(o).scene.faces.size();
  }
  std::string composition(const std::string& body) const {
    return "{\"schema\": \"rc2000sim.composition/1\", " + body + "}";
  }

};

// Both used to go to Assimp ("DXF: no data blocks loaded"): the format was sniffed from 64 KiB.
TEST_F(SceneSourceTest, ALongCommentHeaderOrManyBlankLinesStillMakeATextScene) {
  std::string header;
  while (header.size() < 73 * 1024) header += "# a comment line of a long header, written by a tool\n";
  EXPECT_EQ(faces_of(write("commented.scene", header + kScene)), 2u);
  EXPECT_EQ(faces_of(write("blank.scene", std::string(70000, '\n') + kScene)), 2u);
  EXPECT_EQ(scene_format(header + kScene, "x"), SceneFormat::text);
}

TEST_F(SceneSourceTest, OtherEncodingsAreNamed) {
  std::string utf16 = "\xFF\xFE";
  for (char c : kScene) utf16 += std::string{c, '\0'};
  const std::string path = write("wide.scene", utf16);
  EXPECT_EQ(prepare_error(path), path + ": is UTF-16 (little-endian byte order mark), not UTF-8; save it as UTF-8");
  const std::string no_mark = write("wide2.scene", utf16.substr(2));
  EXPECT_EQ(prepare_error(no_mark),
            no_mark + ": is UTF-16 without a byte order mark (NUL bytes between the characters), not UTF-8; save it as UTF-8");
}

// A Latin-1 material name used to pass the whole solve and fail in report.json's writer.
TEST_F(SceneSourceTest, ALatin1NameInATextSceneIsRefusedNamingLineAndColumn) {
  const std::string path = write("latin1.scene", "# Sch\xF6ne Szene: comments may be anything\n"
                                                 "material caf\xE9 reflectance 0.5 0.5 0.5 emission 1 1 1\n");
  EXPECT_EQ(prepare_error(path), path + ":2: not UTF-8: byte 0xE9 at column 13 (Latin-1 or another 8-bit encoding?); "
                                        "save the file as UTF-8");
}

TEST_F(SceneSourceTest, JsonThatIsNotACompositionSaysWhatItIs) {
  const std::string commented = write("c.json", "// my scene\n" + composition("\"room\": \"cornell-box\""));
  EXPECT_EQ(prepare_error(commented),
            commented + ": line 1: JSON has no comments ('//' here); remove it (a composition is JSON; docs/scenes.md)");
  const std::string inner = write("c2.json", "{\"schema\": \"rc2000sim.composition/1\",\n /* the box */ \"room\": \"cornell-box\"}");
  EXPECT_EQ(prepare_error(inner).rfind(inner + ": line 2: JSON has no comments ('/*' here)", 0), 0u) << prepare_error(inner);
  const std::string wrong = write("w.json", R"({"schema": "rc2000sim.composition/2", "room": "cornell-box"})");
  EXPECT_EQ(prepare_error(wrong), wrong + ": schema: must be \"rc2000sim.composition/1\"");
  const std::string other = write("o.json", R"({"room": "cornell-box"})");
  EXPECT_EQ(prepare_error(other), other + ": JSON, but neither a composition (an object with \"schema\": "
                                          "\"rc2000sim.composition/1\") nor glTF (an object with \"asset\"); docs/scenes.md");
  const std::string broken = write("b.json", "{\"schema\": \"rc2000sim.composition/1\",\n \"room\": }");
  EXPECT_EQ(prepare_error(broken).rfind(broken + ": line 2, column 10: not valid JSON: ", 0), 0u) << prepare_error(broken);
}

// A second "meshes" used to replace the first silently.
TEST_F(SceneSourceTest, ACompositionWithAKeyTwiceIsRefused) {
  write("tetra.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
  const std::string path = write("twice.json", composition("\n\"meshes\": [{\"file\": \"tetra.obj\"}],\n"
                                                           "\"meshes\": [{\"file\": \"tetra.obj\", \"scale\": 2}]"));
  EXPECT_EQ(prepare_error(path), path + ": line 3: key \"meshes\" given twice in the top level (first on line 2); JSON "
                                        "readers keep only one, so remove the other (a composition is JSON; docs/scenes.md)");
  EXPECT_THROW(load_composition(path), SceneFileError);
}

// 200,000 nested arrays (400 KB) ended in SIGSEGV.
TEST_F(SceneSourceTest, ADeeplyNestedCompositionIsRefusedAtTheDepthLimit) {
  const std::string path = write("deep.json", composition("\"room\": " + std::string(200000, '[') + std::string(200000, ']')));
  EXPECT_NE(prepare_error(path).find(": line 1: nested deeper than the limit of 64 arrays and objects"), std::string::npos);
  EXPECT_THROW(load_composition(path), SceneFileError);
}

// A FIFO used to block forever (the sniffer opened it, then the parser opened it again).
TEST_F(SceneSourceTest, AFifoAnywhereIsRefusedByNameAtOnce) {
  const std::string fifo = (dir_ / "room.fifo").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(prepare_error(fifo), fifo + ": is a named pipe (FIFO), not a regular file (a scene file must be one)");
  const std::string room = write("room.json", composition("\"room\": {\"file\": \"room.fifo\"}"));
  EXPECT_EQ(prepare_error(room), fifo + ": is a named pipe (FIFO), not a regular file (a scene file must be one)");
  const std::string mesh = write("mesh.json", composition("\"meshes\": [{\"file\": \"room.fifo\"}]"));
  EXPECT_EQ(prepare_error(mesh), fifo + ": is a named pipe (FIFO), not a regular file (a scene file must be one)");
  EXPECT_FALSE(is_text_scene_file(fifo));
  EXPECT_FALSE(is_composition_file(fifo));
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
}

// `--scene <(cat x.scene)` said "has no faces": the sniffer had read the pipe the parser then opened.
TEST_F(SceneSourceTest, AnAnonymousPipeIsReadOnceForTextAndCompositionsButNotForMeshes) {
  const auto piped = [](const std::string& bytes, const std::function<void(const std::string&)>& use) {
    int fds[2];
    ASSERT_EQ(::pipe(fds), 0);
    ASSERT_EQ(::write(fds[1], bytes.data(), bytes.size()), static_cast<ssize_t>(bytes.size()));
    ::close(fds[1]);
    use("/proc/self/fd/" + std::to_string(fds[0]));
    ::close(fds[0]);
  };
  piped(kScene, [](const std::string& path) { EXPECT_EQ(faces_of(path), 2u); });
  const std::string tetra = write("tetra.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
  piped(composition("\"meshes\": [{\"file\": \"" + tetra + "\"}]"),
        [](const std::string& path) { EXPECT_EQ(faces_of(path), 38u + 4u); });
  piped("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", [](const std::string& path) {
    EXPECT_EQ(prepare_error(path), path + ": a mesh from a pipe; the mesh reader (Assimp) opens files by name (an OBJ "
                                          "finds its .mtl beside it): give the mesh file itself");
  });
}

}  // namespace
}  // namespace rc
