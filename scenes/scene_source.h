// What a scene input is, decided from its whole content, read once. `--scene`, a composition's room
// and its meshes come through here: the bytes are read once (so a pipe given as `--scene <(...)` is
// not read twice, and a FIFO or device is refused by name before any read), then the format is
// decided from all of them (a text scene may start with any number of comment or blank lines), and
// the text readers parse those same bytes. Only Assimp, in its child process, opens a mesh again.
#pragma once

#include <string>
#include <string_view>

#include "io/input_file.h"

namespace rc {

enum class SceneFormat {
  text,         // rc2000sim's own text format (scenes/scene_file.h)
  composition,  // a JSON object with a "schema" (scenes/composition.h), right or wrong
  mesh,         // anything else: Assimp's (scenes/mesh_import.h); glTF is JSON with an "asset"
};

// The format of a scene input's bytes. Text: its first word outside comments is material, quad, tri
// or camera, or it has nothing but comments and blank lines (no NUL byte), which the scene parser
// then calls a scene without faces. JSON (first non-space byte '{' or '['): an object with "schema"
// is a composition, one with "asset" and no "schema" is glTF (a mesh). Throws SceneFileError naming
// `path` for text in UTF-16 or UTF-32 (a byte order mark, or NUL bytes between ASCII characters),
// for JSON that breaks io/json_text.h's rules (comments, duplicate keys, depth, syntax; a ".gltf"
// file goes to Assimp instead), and for JSON that is neither a composition nor glTF.
SceneFormat scene_format(std::string_view bytes, const std::string& path);

struct SceneSource {
  std::string path;
  std::string bytes;  // the whole input, as read once
  SceneFormat format = SceneFormat::mesh;
  bool from_pipe = false;
};

// Reads `path` once (io::read_file, io::kSceneLimitBytes; an anonymous pipe only with
// io::Pipes::read_once) and decides its format. Throws SceneFileError naming the path.
SceneSource read_scene_source(const std::string& path, io::Pipes pipes = io::Pipes::refused);

// True when `path` is a regular file in the text scene format (false for anything unreadable).
bool is_text_scene_file(const std::string& path);

}  // namespace rc
