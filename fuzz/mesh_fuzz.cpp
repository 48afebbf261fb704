// Mesh import through Assimp (scenes/mesh_import.h) on any bytes. import_mesh_file takes a path, so
// the input is written to a file; its first byte picks the extension Assimp sees (obj, ply, off,
// stl: the text and binary formats small enough to fuzz), the rest is the file. A scene or a
// SceneFileError; every other outcome is a finding.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz/fuzz_support.h"
#include "scenes/mesh_import.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  static const char* const kExtensions[] = {"obj", "ply", "off", "stl"};
  const std::string name = std::string("input.") + kExtensions[data[0] % 4];
  const std::string path = rc::fuzz::write_input(name, data + 1, size - 1);
  rc::MeshImportOptions options;
  options.require_emitter = false;  // go on past the materials to the scene built from the faces
  // A file that hangs Assimp is handled (the child is stopped and the error names the file); it must
  // be stopped before libFuzzer's own hang limit (-timeout=10 in scripts/fuzz) takes it for ours.
  options.reader_time_limit = std::chrono::seconds(4);
  try {
    (void)rc::import_mesh_file(path, options);
  } catch (const rc::SceneFileError&) {
    // The documented error.
  }
  return 0;
}
