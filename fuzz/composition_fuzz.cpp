// Scene compositions (scenes/composition.h) on any bytes. load_composition takes a path, so the
// input is written to a file in the scratch folder, beside small files it can name (the dictionary
// fuzz/composition.dict holds their names): a text scene room, an OBJ lamp with its material file,
// an OFF cube. A scene, or a SceneFileError naming the file and the key; every other outcome is a
// finding.
#include <cstddef>
#include <cstdint>

#include "fuzz/fuzz_support.h"
#include "scenes/composition.h"

namespace {

void write_fixtures() {
  rc::fuzz::write_fixture("room.scene",
                          "material white reflectance 0.7 0.7 0.7\n"
                          "material lamp reflectance 0.5 0.5 0.5 emission 5 5 5\n"
                          "quad floor white 0 0 0  0 0 1  1 0 1  1 0 0\n"
                          "quad back white 0 0 1  0 1 1  1 1 1  1 0 1\n"
                          "quad lamp lamp 0.4 0.99 0.4  0.6 0.99 0.4  0.6 0.99 0.6  0.4 0.99 0.6\n");
  rc::fuzz::write_fixture("lamp.mtl", "newmtl glow\nKd 0.5 0.5 0.5\nKe 4 4 4\n");
  rc::fuzz::write_fixture("lamp.obj",
                          "mtllib lamp.mtl\nusemtl glow\n"
                          "v 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nf 1 2 3 4\n");
  rc::fuzz::write_fixture("cube.off",
                          "OFF\n8 6 0\n"
                          "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
                          "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 2 3 7 6\n4 1 2 6 5\n4 0 4 7 3\n");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const bool fixtures_written = (write_fixtures(), true);
  (void)fixtures_written;
  const std::string path = rc::fuzz::write_input("composition.json", data, size);
  try {
    (void)rc::load_composition(path);
  } catch (const rc::SceneFileError&) {
    // The documented error, for the description and for the room and mesh files it reads.
  }
  return 0;
}
