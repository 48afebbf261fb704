#include "scenes/scene_file.h"

#include <cstdio>
#include <optional>
#include <sstream>

#include "io/input_file.h"
#include "io/parse_number.h"
#include "io/text_encoding.h"
#include "scenes/scene_builder.h"

namespace rc {

namespace {

// A word as a message shows it: control bytes (a NUL, an escape) as \xNN, so the message stays
// readable and whole.
std::string shown(const std::string& word) {
  std::string out;
  for (const char c : word) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte != 0x7f) {
      out += c;
      continue;
    }
    char escaped[8];
    std::snprintf(escaped, sizeof escaped, "\\x%02X", byte);
    out += escaped;
  }
  return out;
}

class LineParser {
 public:
  LineParser(const std::string& source, int line_no, const std::string& line)
      : where_(source + ":" + std::to_string(line_no)), in_(line) {}

  const std::string& where() const { return where_; }
  [[noreturn]] void fail(const std::string& problem) const {
    throw SceneFileError(where_ + ": " + problem);
  }
  bool next_word(std::string& word) { return static_cast<bool>(in_ >> word); }
  std::string word(const char* what) {
    std::string w;
    if (!next_word(w)) fail(std::string("missing ") + what);
    return w;
  }
  // The whole word must be a finite decimal number ("1.5x", "nan", "1e999" are refused).
  double number(const char* what) {
    const std::string w = word(what);
    const std::optional<double> value = io::parse_finite(w);
    if (!value) fail("'" + shown(w) + "' is not a finite number (" + what + ")");
    return *value;
  }
  Vec3 vec3(const char* what) {
    const double x = number(what), y = number(what), z = number(what);
    return {x, y, z};
  }
  Spectrum spectrum(const char* what) {
    Spectrum s;
    for (std::size_t b = 0; b < kBands; ++b) s[b] = number(what);
    return s;
  }
  void expect_end() {
    std::string extra;
    if (next_word(extra)) fail("unexpected '" + shown(extra) + "' at end of line");
  }

 private:
  std::string where_;
  std::istringstream in_;
};

void parse_material(LineParser& p, SceneBuilder& builder) {
  Material m;
  m.name = p.word("material name");
  m.emission = Spectrum::uniform(0.0);
  bool has_reflectance = false;
  std::string key;
  while (p.next_word(key)) {
    if (key == "reflectance") {
      m.reflectance = p.spectrum("reflectance value");
      has_reflectance = true;
    } else if (key == "emission") {
      m.emission = p.spectrum("emission value");
    } else {
      p.fail("unknown material property '" + shown(key) + "' (expected reflectance or emission)");
    }
  }
  if (!has_reflectance) p.fail("material '" + m.name + "' needs 'reflectance r g b'");
  try {
    builder.add_material(m);
  } catch (const std::invalid_argument& e) {
    p.fail(e.what());
  }
}

void parse_surface(LineParser& p, SceneBuilder& builder, int corners, bool two_sided) {
  const std::string name = p.word("surface name");
  const std::string material = p.word("material name");
  const int index = builder.find_material(material);
  if (index < 0) p.fail("unknown material '" + shown(material) + "' (define it with 'material' first)");
  std::vector<Vec3> v;
  for (int i = 0; i < corners; ++i) v.push_back(p.vec3("vertex coordinate"));
  p.expect_end();
  try {
    if (two_sided) {
      builder.add_two_sided_surface(name, index, v, p.where());
    } else {
      builder.add_surface(name, index, v, p.where());
    }
  } catch (const std::invalid_argument& e) {
    throw SceneFileError(e.what());  // already starts with the file and line
  }
}

// "two-sided quad ..." or "two-sided tri ...".
void parse_two_sided(LineParser& p, SceneBuilder& builder) {
  std::string shape;
  if (!p.next_word(shape)) p.fail("'two-sided' needs a surface: two-sided quad ... or two-sided tri ...");
  if (shape == "quad") return parse_surface(p, builder, 4, true);
  if (shape == "tri") return parse_surface(p, builder, 3, true);
  p.fail("'two-sided' is followed by '" + shown(shape) + "' (expected quad or tri)");
}

void parse_camera(LineParser& p, SceneBuilder& builder) {
  Camera c;
  c.position = p.vec3("camera position");
  c.look_at = p.vec3("camera look-at point");
  c.up = p.vec3("camera up vector");
  c.vertical_fov_deg = p.number("vertical field of view (degrees)");
  p.expect_end();
  try {
    check_camera(c);
  } catch (const std::invalid_argument& e) {
    p.fail(e.what());
  }
  builder.set_camera(c);
}

}  // namespace

LoadedScene parse_scene_text(const std::string& text, const std::string& source_name) {
  if (const std::string wide = io::wide_encoding(text); !wide.empty())
    throw SceneFileError(source_name + ": " + wide + "; save it as UTF-8");
  SceneBuilder builder(source_name);
  std::istringstream in(io::without_byte_order_mark(text));
  std::string line;
  int line_no = 0;
  int camera_line = 0;  // a second camera would silently replace the first
  while (std::getline(in, line)) {
    ++line_no;
    if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    LineParser p(source_name, line_no, line);
    // Names reach report.json and the terminal: they must be UTF-8 (comments may be anything).
    if (const std::size_t bad = io::first_invalid_utf8(line); bad != std::string::npos) {
      char byte[8];
      std::snprintf(byte, sizeof byte, "0x%02X", static_cast<unsigned char>(line[bad]));
      p.fail(std::string("not UTF-8: byte ") + byte + " at column " + std::to_string(bad + 1) +
             " (Latin-1 or another 8-bit encoding?); save the file as UTF-8");
    }
    std::string keyword;
    if (!p.next_word(keyword)) continue;
    if (keyword == "material") {
      parse_material(p, builder);
    } else if (keyword == "quad") {
      parse_surface(p, builder, 4, false);
    } else if (keyword == "tri") {
      parse_surface(p, builder, 3, false);
    } else if (keyword == "two-sided") {
      parse_two_sided(p, builder);
    } else if (keyword == "camera") {
      if (camera_line > 0) p.fail("a second camera (the first is on line " + std::to_string(camera_line) + "); a scene has one");
      camera_line = line_no;
      parse_camera(p, builder);
    } else {
      p.fail("unknown keyword '" + shown(keyword) + "' (expected material, quad, tri, two-sided or camera)");
    }
  }
  try {
    return {builder.build(), builder.warnings()};
  } catch (const std::invalid_argument& e) {
    throw SceneFileError(source_name + ": " + e.what());
  }
}

LoadedScene load_scene_file(const std::string& path) {
  std::string text;
  try {
    text = io::read_file(path, io::kSceneLimitBytes, "a scene file");
  } catch (const io::InputFileError& e) {
    throw SceneFileError(e.what());
  }
  return parse_scene_text(text, path);
}

}  // namespace rc
