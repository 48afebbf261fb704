#include "scenes/composition.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <utility>

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include "io/input_file.h"
#include "io/json_text.h"
#include "scenes/cornell_box.h"
#include "scenes/mesh_import.h"
#include "scenes/scene_builder.h"
#include "scenes/scene_source.h"

namespace rc {

namespace {

constexpr const char* kSchema = "rc2000sim.composition/1";

// The description being read: its path (for errors and relative files) and its JSON.
class Description {
 public:
  Description(std::string path, nlohmann::json json) : path_(std::move(path)), json_(std::move(json)) {}

  [[noreturn]] void fail(const std::string& key, const std::string& problem) const {
    throw SceneFileError(path_ + ": " + key + ": " + problem);
  }

  Vec3 vec3(const nlohmann::json& j, const std::string& key) const {
    if (!j.is_array() || j.size() != 3) fail(key, "must be an array of 3 numbers");
    Vec3 v;
    for (int i = 0; i < 3; ++i) {
      if (!j[i].is_number()) fail(key, "must be an array of 3 numbers");
      v[i] = j[i].get<double>();
      if (!std::isfinite(v[i])) fail(key, "must be finite");
    }
    return v;
  }

  double number(const nlohmann::json& j, const std::string& key) const {
    if (!j.is_number() || !std::isfinite(j.get<double>())) fail(key, "must be a finite number");
    return j.get<double>();
  }

  // Components in [0, below).
  Spectrum spectrum(const nlohmann::json& j, const std::string& key, double below) const {
    const Vec3 v = vec3(j, key);
    Spectrum s;
    for (std::size_t b = 0; b < kBands; ++b) {
      const double x = v[static_cast<int>(b)];
      if (x < 0 || x >= below) fail(key, "components must be at least 0 and below " + std::to_string(below));
      s.band[b] = x;
    }
    return s;
  }

  std::string file(const nlohmann::json& j, const std::string& key) const {
    if (!j.is_string() || j.get<std::string>().empty()) fail(key, "must be a file name");
    const std::filesystem::path p(j.get<std::string>());
    return p.is_absolute() ? p.string() : (std::filesystem::path(path_).parent_path() / p).string();
  }

  void only_keys(const nlohmann::json& object, const std::string& where, std::initializer_list<const char*> keys) const {
    if (!object.is_object()) fail(where, "must be an object");
    for (const auto& item : object.items()) {
      if (std::find_if(keys.begin(), keys.end(), [&](const char* k) { return item.key() == k; }) == keys.end()) {
        std::string allowed;
        for (const char* k : keys) allowed += std::string(allowed.empty() ? "" : ", ") + k;
        fail(where + "." + item.key(), "unknown key (allowed: " + allowed + ")");
      }
    }
  }

  const std::string& path() const { return path_; }
  const nlohmann::json& json() const { return json_; }

 private:
  std::string path_;
  nlohmann::json json_;
};

LoadedScene load_room(const Description& d) {
  if (!d.json().contains("room")) return {cornell_box(), {}};
  const nlohmann::json& room = d.json()["room"];
  if (room.is_string()) {
    if (room.get<std::string>() != "cornell-box") d.fail("room", "must be \"cornell-box\" or {\"file\": ...}");
    return {cornell_box(), {}};
  }
  d.only_keys(room, "room", {"file"});
  if (!room.contains("file")) d.fail("room.file", "missing");
  const std::string file = d.file(room["file"], "room.file");
  const SceneSource source = read_scene_source(file);  // read once; a FIFO or device is refused by name
  if (source.format == SceneFormat::composition) d.fail("room.file", file + " is a composition; compositions do not nest (name its room or meshes here)");
  if (source.format == SceneFormat::text) return parse_scene_text(source.bytes, file);
  MeshImportOptions o;
  o.require_emitter = false;  // the description may add the light
  return import_mesh_file(file, o);
}

struct Box {
  Vec3 lo{std::numeric_limits<double>::max()}, hi{std::numeric_limits<double>::lowest()};
  void add(const Vec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
};

// The mesh's faces moved into place: rotate about its own centre, then scale and translate, or fit
// its bounding box (uniform scale, centred) into the given box.
std::vector<Face> place(const Description& d, const nlohmann::json& m, const std::string& key, std::vector<Face> faces) {
  Box box;
  for (const Face& f : faces)
    for (const Vec3& v : {f.tri.v0, f.tri.v1, f.tri.v2}) box.add(v);
  const Vec3 centre = (box.lo + box.hi) * 0.5;
  glm::dmat4 rotation(1.0);
  if (m.contains("rotate")) {
    d.only_keys(m["rotate"], key + ".rotate", {"axis", "degrees"});
    const Vec3 axis = d.vec3(m["rotate"].value("axis", nlohmann::json()), key + ".rotate.axis");
    if (glm::length(axis) == 0) d.fail(key + ".rotate.axis", "must not be zero");
    rotation = glm::rotate(glm::dmat4(1.0), glm::radians(d.number(m["rotate"].value("degrees", nlohmann::json()),
                                                                 key + ".rotate.degrees")),
                           glm::normalize(axis));
  }
  auto rotated = [&](const Vec3& p) { return Vec3(rotation * glm::dvec4(p - centre, 1.0)); };
  Box turned;
  for (const Face& f : faces)
    for (const Vec3& v : {f.tri.v0, f.tri.v1, f.tri.v2}) turned.add(rotated(v));

  double scale = 1;
  Vec3 offset = centre;
  if (m.contains("fit_into")) {
    if (m.contains("scale") || m.contains("translate")) d.fail(key + ".fit_into", "excludes scale and translate");
    d.only_keys(m["fit_into"], key + ".fit_into", {"min", "max"});
    const Vec3 lo = d.vec3(m["fit_into"].value("min", nlohmann::json()), key + ".fit_into.min");
    const Vec3 hi = d.vec3(m["fit_into"].value("max", nlohmann::json()), key + ".fit_into.max");
    if (!(hi.x > lo.x && hi.y > lo.y && hi.z > lo.z)) d.fail(key + ".fit_into", "max must exceed min on every axis");
    const Vec3 size = turned.hi - turned.lo;
    scale = std::numeric_limits<double>::max();
    for (int i = 0; i < 3; ++i) {
      if (size[i] > 0) scale = std::min(scale, (hi[i] - lo[i]) / size[i]);
    }
    // Centred in the box, resting on its floor (min y).
    const Vec3 mid = (turned.lo + turned.hi) * 0.5;
    offset = Vec3((lo.x + hi.x) / 2, lo.y, (lo.z + hi.z) / 2) - Vec3(mid.x, turned.lo.y, mid.z) * scale;
  } else {
    if (m.contains("scale")) {
      scale = d.number(m["scale"], key + ".scale");
      if (!(scale > 0)) d.fail(key + ".scale", "must be positive");
    }
    offset = centre * 1.0;
    if (m.contains("translate")) offset += d.vec3(m["translate"], key + ".translate");
  }
  for (Face& f : faces) {
    for (Vec3* v : {&f.tri.v0, &f.tri.v1, &f.tri.v2}) *v = rotated(*v) * scale + offset;
  }
  return faces;
}

// Appends `part` to `scene`, its materials after the scene's (or `override` for all its faces).
void append(Scene& scene, Scene part, const Material* override_material) {
  const int base = static_cast<int>(scene.materials.size());
  const int surfaces = scene.faces.empty() ? 0 : scene.faces.back().surface + 1;
  // The part's surfaces keep their names after the scene's (a mesh's unnamed ones take its name).
  int part_surfaces = static_cast<int>(part.surface_names.size());
  for (const Face& f : part.faces) part_surfaces = std::max(part_surfaces, f.surface + 1);
  part.surface_names.resize(static_cast<std::size_t>(part_surfaces), part.name);
  scene.surface_names.resize(static_cast<std::size_t>(surfaces));
  scene.surface_names.insert(scene.surface_names.end(), part.surface_names.begin(), part.surface_names.end());
  if (override_material != nullptr) {
    scene.materials.push_back(*override_material);
  } else {
    for (Material m : part.materials) {
      m.name = part.name + ": " + m.name;
      scene.materials.push_back(m);
    }
  }
  for (Face f : part.faces) {
    f.material = override_material != nullptr ? base : base + f.material;
    f.surface += surfaces;
    scene.faces.push_back(f);
  }
}

}  // namespace

namespace {

nlohmann::json parse_description(const std::string& text, const std::string& path) {
  try {
    return io::parse_json_text(text, path);  // depth, duplicate keys, comments, UTF-8, syntax
  } catch (const io::InputFileError& e) {
    throw SceneFileError(e.what());
  }
}

// The schema key holds this format's name; any other value, or another type, is not it (value()
// would throw a type_error on a number).
bool has_schema(const nlohmann::json& object) {
  const auto it = object.find("schema");
  return it != object.end() && it->is_string() && it->get<std::string>() == kSchema;
}

}  // namespace

bool is_composition_file(const std::string& path) {
  try {
    const SceneSource source = read_scene_source(path);
    return source.format == SceneFormat::composition && has_schema(parse_description(source.bytes, path));
  } catch (const SceneFileError&) {
    return false;
  }
}

LoadedScene load_composition(const std::string& path) {
  std::string text;
  try {
    text = io::read_file(path, io::kSceneLimitBytes, "a scene file");
  } catch (const io::InputFileError& e) {
    throw SceneFileError(e.what());
  }
  return load_composition_text(text, path);
}

LoadedScene load_composition_text(const std::string& text, const std::string& path) {
  const nlohmann::json json = parse_description(text, path);
  const Description d(path, json);
  d.only_keys(json, "(top level)", {"schema", "room", "meshes", "light"});
  if (!has_schema(json)) d.fail("schema", std::string("must be \"") + kSchema + "\"");

  LoadedScene out = load_room(d);
  out.scene.name = std::filesystem::path(path).filename().string();
  const nlohmann::json meshes = json.value("meshes", nlohmann::json::array());
  if (!meshes.is_array()) d.fail("meshes", "must be an array");
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    const std::string key = "meshes[" + std::to_string(i) + "]";
    const nlohmann::json& m = meshes[i];
    d.only_keys(m, key, {"file", "rotate", "fit_into", "scale", "translate", "material", "two_sided"});
    if (!m.contains("file")) d.fail(key + ".file", "missing");
    MeshImportOptions o;
    o.require_emitter = false;
    const std::string file = d.file(m["file"], key + ".file");
    // Assimp would say only "No suitable reader found" for our own formats.
    const SceneFormat format = read_scene_source(file).format;
    if (format == SceneFormat::composition) d.fail(key + ".file", file + " is a composition; compositions do not nest (name its meshes here)");
    if (format == SceneFormat::text) d.fail(key + ".file", file + " is a text scene; a mesh must be a mesh file (OBJ, PLY, OFF, STL, ...), or use it as the room");
    LoadedScene mesh = import_mesh_file(file, o);
    mesh.scene.faces = place(d, m, key, std::move(mesh.scene.faces));
    if (m.contains("two_sided")) {
      if (!m["two_sided"].is_boolean()) d.fail(key + ".two_sided", "must be true or false");
      if (m["two_sided"].get<bool>()) add_back_faces(mesh.scene);  // thin shells: leaves, paper, plates
    }
    Material override_material;
    const bool overridden = m.contains("material");
    if (overridden) {
      d.only_keys(m["material"], key + ".material", {"reflectance", "emission"});
      override_material.name = mesh.scene.name + " (override)";
      override_material.reflectance = d.spectrum(m["material"].value("reflectance", nlohmann::json::array({0.5, 0.5, 0.5})),
                                                 key + ".material.reflectance", 1.0);
      if (m["material"].contains("emission")) {
        override_material.emission = d.spectrum(m["material"]["emission"], key + ".material.emission", 1e300);
      }
    }
    out.warnings.insert(out.warnings.end(), mesh.warnings.begin(), mesh.warnings.end());
    append(out.scene, std::move(mesh.scene), overridden ? &override_material : nullptr);
  }
  if (json.contains("light")) {
    const nlohmann::json& l = json["light"];
    d.only_keys(l, "light", {"corners", "emission"});
    if (!l.contains("corners") || !l["corners"].is_array() || l["corners"].size() != 4) {
      d.fail("light.corners", "must be 4 corners, wound so that (c1 - c0) x (c2 - c0) faces the room");
    }
    std::vector<Vec3> c;
    for (int k = 0; k < 4; ++k) c.push_back(d.vec3(l["corners"][k], "light.corners[" + std::to_string(k) + "]"));
    // Through the builder, as every surface: a folded quad is an error, a zero-area half a warning.
    SceneBuilder light("light");
    const int material =
        light.add_material({"light", Spectrum{}, d.spectrum(l.value("emission", nlohmann::json()), "light.emission", 1e300)});
    try {
      light.add_surface("light", material, c, path + ": light.corners");
    } catch (const std::invalid_argument& e) {
      throw SceneFileError(e.what());  // starts with the file and the key
    }
    if (light.face_count() == 0) d.fail("light.corners", "the light has no area");
    out.warnings.insert(out.warnings.end(), light.warnings().begin(), light.warnings().end());
    append(out.scene, light.build(), nullptr);
  }
  if (out.scene.faces.empty()) d.fail("(top level)", "the composed scene has no faces");
  if (!out.scene.emits_light()) d.fail("light", "nothing in the composed scene emits light: add a light or an emissive material");
  return out;
}

}  // namespace rc
