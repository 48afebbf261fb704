// From a scene source to the solver's input: load (or embed), refine, split, normalise, patch.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "scenes/scene.h"

namespace rc {

// Upper bounds on what a scene may grow to, checked before anything is allocated, so that a typo
// (--face-levels 8 --patch-levels 8: 10^11 patches) is an error naming the option instead of an
// out-of-memory kill or a run of days.
// - Patches: a solve holds about 350 bytes per patch (2,490,368 patches took 861 MB,
//   docs/results/performance.md); 2^24 patches is about 6 GB, and indices stay far inside int.
// - Faces: about 1 KB per face with its patch (155,648 faces and patches took 150 MB there: the
//   scene, the visibility structures and the board's face banks); 2^22 faces is about 4 GB.
constexpr std::uint64_t kMaxFaces = std::uint64_t{1} << 22;
constexpr std::uint64_t kMaxPatches = std::uint64_t{1} << 24;

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

// Throws std::invalid_argument naming the option (--faces, --face-levels, --patch-levels,
// --patch-size) and the limit when the scene would exceed kMaxFaces or kMaxPatches, and passes on
// the loaders' SceneFileError and normalise()'s errors.
PreparedScene prepare_scene(const SceneOptions& options);
// The same, reporting each phase (loading, refining, splitting, patching) to `progress` as it starts:
// meshes and scenes at real size take seconds there (docs/results/performance.md).
PreparedScene prepare_scene(const SceneOptions& options, const std::function<void(const std::string&)>& progress);

}  // namespace rc
