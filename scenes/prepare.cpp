#include "scenes/prepare.h"

#include "scenes/composition.h"
#include "scenes/cornell_box.h"
#include "scenes/mesh_import.h"
#include "scenes/normalise.h"
#include "scenes/scene_file.h"
#include "scenes/subdivide.h"

namespace rc {

PreparedScene prepare_scene(const SceneOptions& options) {
  PreparedScene out;
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
  if (options.face_target > 0) scene.faces = refine_to_count(scene.faces, options.face_target);
  scene.faces = split_faces(scene.faces, options.face_levels);
  normalise(scene);
  scene.patches = options.patch_size > 0 ? make_patches_of_size(scene.faces, options.patch_size)
                                         : make_patches(scene.faces, options.patch_levels);
  return out;
}

}  // namespace rc
