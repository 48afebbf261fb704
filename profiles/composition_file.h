// A scene composition (docs/scenes.md, "Composing a scene"; schema rc2000sim.composition/1) read at
// the edge into typed values: which room, which meshes placed how, which light. Each key is checked
// for its shape here (objects with known keys only, arrays of three finite numbers, file names made
// relative to the description's folder); scenes/composition.cpp builds the scene from it and checks
// what needs the geometry (ranges of colours, a zero axis, an empty box, a positive scale).
#pragma once

#include <array>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace rc::profiles {

using Triple = std::array<double, 3>;

struct CompositionRotate {
  Triple axis{};
  double degrees = 0;
};

struct CompositionBox {
  Triple min{}, max{};
};

struct CompositionMaterial {
  Triple reflectance{0.5, 0.5, 0.5};
  std::optional<Triple> emission;
};

struct CompositionMesh {
  std::string key;   // "meshes[2]", for errors
  std::string file;  // relative to the description's folder, resolved
  std::optional<CompositionRotate> rotate;
  std::optional<CompositionBox> fit_into;  // excludes scale and translate
  std::optional<double> scale;
  std::optional<Triple> translate;
  std::optional<CompositionMaterial> material;
  bool two_sided = false;
};

struct CompositionLight {
  std::array<Triple, 4> corners{};
  Triple emission{};
};

// The picture's camera, in the room's units (docs/scenes.md, "Composing a scene").
struct CompositionCamera {
  Triple position{}, look_at{};
  Triple up{0, 1, 0};
  std::optional<double> fov_deg;  // none: the Cornell camera's 39.3 degrees
};

struct CompositionFile {
  std::optional<std::string> room_file;  // none: the embedded Cornell Box
  std::optional<CompositionCamera> camera;  // none: the room's camera (the Cornell Box's), else the scene framed
  std::vector<CompositionMesh> meshes;
  std::optional<CompositionLight> light;
};

// "<path>: <key>: <problem>".
class CompositionError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// Throws CompositionError for a bad description and io::InputFileError for text that is not JSON.
CompositionFile parse_composition(std::string_view text, const std::string& path);
// True when the text is a JSON object whose "schema" is rc2000sim.composition/1 (false for anything
// else, JSON or not).
bool has_composition_schema(std::string_view text, const std::string& path);

}  // namespace rc::profiles
