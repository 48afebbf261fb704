#include "scenes/prepare.h"

#include <cstdio>
#include <stdexcept>

#include "scenes/composition.h"
#include "scenes/cornell_box.h"
#include "scenes/mesh_import.h"
#include "scenes/normalise.h"
#include "scenes/scene_file.h"
#include "scenes/scene_source.h"
#include "scenes/sheet_finder.h"
#include "scenes/subdivide.h"

namespace rc {

namespace {

// "<what> <count> <unit>, more than the limit of ...".
void check_limit(std::uint64_t count, std::uint64_t limit, const std::string& what, const char* unit,
                 const char* limit_name) {
  if (count <= limit) return;
  throw std::invalid_argument(what + " " + std::to_string(count) + " " + unit + ", more than the limit of " +
                              std::to_string(limit) + " (" + limit_name + ", set by the memory a solve needs; " +
                              "docs/scenes.md, Limits)");
}

// Levels outside 0..8 are refused by split_faces and make_patches themselves.
bool valid_levels(int levels) { return levels >= 0 && levels <= 8; }

std::string format_number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

// Throws naming the option and the first face that cannot get patches that small.
std::uint64_t patches_of_size(const std::vector<Face>& faces, double size) {
  std::uint64_t count = 0;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    try {
      count += std::uint64_t{1} << (2 * levels_for_size(faces[f].tri, size));
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("--patch-size " + format_number(size) + ": face " + std::to_string(f) + ": " +
                                  e.what() + " (normalised units); refine the faces first (--faces, --face-levels) " +
                                  "or ask for larger patches");
    }
  }
  return count;
}

// Our text format, a composition (JSON), or any format Assimp reads, recognised by content. The
// file is read once (scenes/scene_source.h): `--scene <(...)`, an anonymous pipe, is allowed, and
// the text readers parse the bytes read; Assimp opens files by name, so a mesh must be a file.
LoadedScene load_scene(const std::string& path) {
  SceneSource source = read_scene_source(path, io::Pipes::read_once);
  if (source.format == SceneFormat::text) return parse_scene_text(source.bytes, path);
  if (source.format == SceneFormat::composition) return load_composition_text(source.bytes, path);
  if (source.from_pipe) {
    throw SceneFileError(path + ": a mesh from a pipe; the mesh reader (Assimp) opens files by name (an OBJ "
                                "finds its .mtl beside it): give the mesh file itself");
  }
  source.bytes = std::string();  // Assimp's child process reads the file itself
  return import_mesh_file(path);
}

}  // namespace

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
    LoadedScene loaded = load_scene(options.file);
    out.scene = std::move(loaded.scene);
    out.warnings = std::move(loaded.warnings);
  }
  Scene& scene = out.scene;
  check_limit(scene.faces.size(), kMaxFaces, options.file + " has", "faces", "kMaxFaces");
  if (options.face_target < 0) throw std::invalid_argument("--faces must not be negative, got " + std::to_string(options.face_target));
  check_limit(static_cast<std::uint64_t>(options.face_target), kMaxFaces, "--faces asks for", "faces", "kMaxFaces");
  // Exact, and every area comparison of the refinement comes out as at the scene's own size.
  rescale_by_power_of_two(scene);
  if (options.face_target > 0) {
    phase("refining " + std::to_string(scene.faces.size()) + " faces to " + std::to_string(options.face_target));
    scene.faces = refine_to_count(scene.faces, options.face_target);
  }
  if (valid_levels(options.face_levels)) {
    const std::uint64_t faces = std::uint64_t{scene.faces.size()} << (2 * options.face_levels);
    check_limit(faces, kMaxFaces, "--face-levels " + std::to_string(options.face_levels) + " makes", "faces", "kMaxFaces");
    // Uniform patches are counted before the faces are split; patches of a size need the geometry.
    if (options.patch_size <= 0 && valid_levels(options.patch_levels)) {
      check_limit(faces << (2 * options.patch_levels), kMaxPatches,
                  "--patch-levels " + std::to_string(options.patch_levels) + " makes", "patches", "kMaxPatches");
    }
  }
  if (options.face_levels > 0) phase("splitting " + std::to_string(scene.faces.size()) + " faces");
  scene.faces = split_faces(scene.faces, options.face_levels);
  if (!scene.camera_given && !scene.faces.empty()) {  // a mesh or a scene file without a camera: frame it
    Vec3 lo = scene.faces.front().tri.v0, hi = lo;
    for (const Face& f : scene.faces)
      for (const Vec3& v : {f.tri.v0, f.tri.v1, f.tri.v2}) lo = glm::min(lo, v), hi = glm::max(hi, v);
    scene.camera = frame_bounds(lo, hi);
  }
  normalise(scene);
  // Two-sided surfaces (faces back to back) become sheets, their faces contiguous, before patches
  // name faces by index (scenes/sheet_finder.h).
  find_sheets(scene);
  if (options.patch_size > 0) {
    check_limit(patches_of_size(scene.faces, options.patch_size), kMaxPatches,
                "--patch-size " + format_number(options.patch_size) + " makes", "patches", "kMaxPatches");
  }
  phase("making patches of " + std::to_string(scene.faces.size()) + " faces");
  scene.patches = options.patch_size > 0 ? make_patches_of_size(scene.faces, options.patch_size)
                                         : make_patches(scene.faces, options.patch_levels);
  return out;
}

}  // namespace rc
