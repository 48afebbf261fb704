// Scenes someone else's tool made: every format Assimp reads (OBJ, PLY, STL, glTF, Collada, 3DS,
// OFF, ...), recognised by content as well as by extension. Polygons are triangulated, identical
// vertices joined, node transforms applied; points and lines are skipped and zero-area faces
// dropped (both counted in the warnings). Each mesh's material gives its reflectance (diffuse
// colour, RGB bands as the solver uses them) and emission (emissive colour); docs/scenes.md,
// "Meshes". Errors name the file and the reason.
#pragma once

#include <chrono>
#include <cstddef>
#include <optional>
#include <string>

#include "scenes/scene_file.h"
#include "scenes/scene_source.h"  // is_text_scene_file, which callers of this header used

namespace rc {

struct MeshImportOptions {
  // Diffuse colour components at or above this are clamped to it, with a warning: a reflectance
  // must be below 1 for the solution to converge, and many models use pure white (1, 1, 1).
  double max_reflectance = 0.99;
  // The reflectance of a material that gives no diffuse colour (documented default).
  double default_reflectance = 0.5;
  bool require_emitter = true;  // a scene that emits no light is an error
  // How long the reader (Assimp, in a child process) may take before the file counts as one that
  // hangs it. Unset: a minute plus a second per MiB of file. The fuzz harness sets a few seconds,
  // below libFuzzer's own hang limit.
  std::optional<std::chrono::seconds> reader_time_limit;
};

// Throws SceneFileError naming the file: it is not a regular file of at most io::kSceneLimitBytes,
// Assimp could not read it, it has no triangles, or (with require_emitter) none of its materials
// emits light.
LoadedScene import_mesh_file(const std::string& path, const MeshImportOptions& options = {});

}  // namespace rc
