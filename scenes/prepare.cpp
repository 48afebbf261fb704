#include "scenes/prepare.h"

#include "scenes/composition.h"
#include "scenes/cornell_box.h"
#include "scenes/mesh_import.h"
#include "scenes/normalise.h"
#include "scenes/scene_file.h"
#include "scenes/subdivide.h"

namespace rc {

PreparedScene prepare_scene(const SceneOptions& options) { return prepare_scene(options, nullptr); }

PreparedScene prepare_scene(const SceneOptions& options, const std::function<void(const std::string&)>& progress) {
  auto phase = [&](const std::string& what) {
    if (progress) progress(what);
  };
  PreparedScene out;
  phase(options.file.empty() ? "building the Cornell Box" : "loading " + options.file);
  if (options.file.empty()) {
    out.scene = cornell_box();
  } else {
    // Our text format, or any format Assimp reads (recognised by content).
    // Our text format, a composition (JSON), or any format Assimp reads (recognised by content).
    LoadedScene loaded = is_text_scene_file(options.file)    ? load_scene_file(options.file)
                         : is_composition_file(options.file) ? load_composition(options.file)
                                                             : import_mesh_file(options.file);
    out.scene = std::move(loaded.scene);
    out.warnings = std::move(loaded.warnings);
  }
  Scene& scene = out.scene;
  if (options.face_target > 0) {
    phase("refining " + std::to_string(scene.faces.size()) + " faces to " + std::to_string(options.face_target));
    scene.faces = refine_to_count(scene.faces, options.face_target);
  }
  if (options.face_levels > 0) phase("splitting " + std::to_string(scene.faces.size()) + " faces");
  scene.faces = split_faces(scene.faces, options.face_levels);
  normalise(scene);
  phase("making patches of " + std::to_string(scene.faces.size()) + " faces");
  scene.patches = options.patch_size > 0 ? make_patches_of_size(scene.faces, options.patch_size)
                                         : make_patches(scene.faces, options.patch_levels);
  return out;
}

}  // namespace rc
