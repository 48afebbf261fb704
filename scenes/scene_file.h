// The text scene format (docs/scenes.md). Errors name the file, the line and the problem.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "scenes/scene.h"

namespace rc {

class SceneFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct LoadedScene {
  Scene scene;                        // faces only: not normalised, no patches yet
  std::vector<std::string> warnings;  // e.g. zero-area faces dropped
};

LoadedScene load_scene_file(const std::string& path);
// Parses scene text; `source_name` is used in error messages in place of a path.
LoadedScene parse_scene_text(const std::string& text, const std::string& source_name);

}  // namespace rc
