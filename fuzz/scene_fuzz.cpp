// The text scene parser (scenes/scene_file.h) on any bytes: a scene, or a SceneFileError naming
// the line. Every other outcome is a finding.
#include <cstddef>
#include <cstdint>
#include <string>

#include "scenes/scene_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    (void)rc::parse_scene_text(text, "fuzz.scene");
  } catch (const rc::SceneFileError&) {
    // The documented error.
  }
  return 0;
}
