// From a scene source to the solver's input: load (or embed), refine, split, normalise, patch.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "scenes/scene.h"

namespace rc {

struct SceneOptions {
  std::string file;       // empty: the embedded Cornell Box
  int face_target = 0;    // > 0: refine to exactly this many faces first (longest-edge bisection)
  int face_levels = 0;    // then split every face into 4^face_levels faces
  int patch_levels = 3;   // then split every face into 4^patch_levels patches
  double patch_size = 0;  // > 0: instead, patches of at most this edge length (normalised units)
};

struct PreparedScene {
  Scene scene;
  std::vector<std::string> warnings;
};

PreparedScene prepare_scene(const SceneOptions& options);
// The same, reporting each phase (loading, refining, splitting, patching) to `progress` as it starts:
// meshes and scenes at real size take seconds there (docs/results/performance.md).
PreparedScene prepare_scene(const SceneOptions& options, const std::function<void(const std::string&)>& progress);

}  // namespace rc
