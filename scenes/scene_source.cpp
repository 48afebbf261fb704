#include "scenes/scene_source.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <optional>
#include <vector>

#include "io/input_file.h"
#include "io/json_keys.h"
#include "io/text_encoding.h"
#include "scenes/scene_file.h"

namespace rc {

namespace {

constexpr std::string_view kSpace = " \t\n\v\f\r";  // std::isspace in the C locale

// Our format's first word outside comments and blank lines, or "" for a text of nothing else.
// The whole text is looked at: a comment header of any length is still ours.
std::string_view first_word(std::string_view text) {
  std::size_t at = 0;
  while (at < text.size()) {
    const std::size_t start = text.find_first_not_of(kSpace, at);
    if (start == std::string_view::npos) return "";
    if (text[start] == '#') {
      const std::size_t end = text.find('\n', start);
      if (end == std::string_view::npos) return "";
      at = end + 1;
      continue;
    }
    const std::size_t end = text.find_first_of(kSpace, start);
    return text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start);
  }
  return "";
}

bool is_keyword(std::string_view word) {
  return word == "material" || word == "quad" || word == "tri" || word == "two-sided" || word == "camera";
}

bool is_gltf_name(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".gltf";
}

SceneFormat json_format(std::string_view text, const std::string& path) {
  std::optional<std::vector<std::string>> keys;
  try {
    keys = io::json_object_keys(text, path);
  } catch (const io::InputFileError& e) {
    if (is_gltf_name(path)) return SceneFormat::mesh;  // Assimp's glTF reader has its own errors
    throw SceneFileError(std::string(e.what()) + " (a composition is JSON; docs/scenes.md)");
  }
  const auto has = [&](const char* key) { return keys && std::find(keys->begin(), keys->end(), key) != keys->end(); };
  if (has("schema")) return SceneFormat::composition;
  if (has("asset")) return SceneFormat::mesh;
  throw SceneFileError(path + ": JSON, but neither a composition (an object with \"schema\": "
                              "\"rc2000sim.composition/1\") nor glTF (an object with \"asset\"); docs/scenes.md");
}

}  // namespace

SceneFormat scene_format(std::string_view bytes, const std::string& path) {
  const std::string wide = io::wide_encoding(bytes);
  if (!wide.empty()) throw SceneFileError(path + ": " + wide + "; save it as UTF-8");
  const std::string_view text = bytes.substr(0, 3) == io::kUtf8ByteOrderMark ? bytes.substr(3) : bytes;
  const std::string_view word = first_word(text);
  if (is_keyword(word)) return SceneFormat::text;
  if (word.empty()) return text.find('\0') == std::string_view::npos ? SceneFormat::text : SceneFormat::mesh;
  // JSON, or something with a JSON comment before it (an OBJ or OFF never starts with '/').
  if (word[0] == '{' || word[0] == '[' || word.substr(0, 2) == "//" || word.substr(0, 2) == "/*") return json_format(text, path);
  return SceneFormat::mesh;
}

SceneSource read_scene_source(const std::string& path, io::Pipes pipes) {
  SceneSource s;
  s.path = path;
  try {
    s.from_pipe = pipes == io::Pipes::read_once && io::is_anonymous_pipe(path);
    s.bytes = io::read_file(path, io::kSceneLimitBytes, "a scene file", pipes);
  } catch (const io::InputFileError& e) {
    throw SceneFileError(e.what());
  }
  s.format = scene_format(s.bytes, path);
  return s;
}

bool is_text_scene_file(const std::string& path) {
  try {
    return read_scene_source(path).format == SceneFormat::text;
  } catch (const SceneFileError&) {
    return false;
  }
}

}  // namespace rc
