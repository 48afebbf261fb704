#include "profiles/composition_file.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <initializer_list>

#include "io/input_file.h"
#include "io/json_text.h"

namespace rc::profiles {

namespace {

using nlohmann::json;

constexpr const char* kSchema = "rc2000sim.composition/1";

// The description being read: its path (for errors and relative files).
class Reader {
 public:
  explicit Reader(std::string path) : path_(std::move(path)) {}

  [[noreturn]] void fail(const std::string& key, const std::string& problem) const {
    throw CompositionError(path_ + ": " + key + ": " + problem);
  }

  Triple triple(const json& j, const std::string& key) const {
    if (!j.is_array() || j.size() != 3) fail(key, "must be an array of 3 numbers");
    Triple v{};
    for (std::size_t i = 0; i < 3; ++i) {
      if (!j[i].is_number()) fail(key, "must be an array of 3 numbers");
      v[i] = j[i].get<double>();
      if (!std::isfinite(v[i])) fail(key, "must be finite");
    }
    return v;
  }

  double number(const json& j, const std::string& key) const {
    if (!j.is_number() || !std::isfinite(j.get<double>())) fail(key, "must be a finite number");
    return j.get<double>();
  }

  std::string file(const json& j, const std::string& key) const {
    if (!j.is_string() || j.get<std::string>().empty()) fail(key, "must be a file name");
    const std::filesystem::path p(j.get<std::string>());
    return p.is_absolute() ? p.string() : (std::filesystem::path(path_).parent_path() / p).string();
  }

  void only_keys(const json& object, const std::string& where, std::initializer_list<const char*> keys) const {
    if (!object.is_object()) fail(where, "must be an object");
    for (const auto& item : object.items()) {
      if (std::find_if(keys.begin(), keys.end(), [&](const char* k) { return item.key() == k; }) == keys.end()) {
        std::string allowed;
        for (const char* k : keys) allowed += std::string(allowed.empty() ? "" : ", ") + k;
        fail(where + "." + item.key(), "unknown key (allowed: " + allowed + ")");
      }
    }
  }

 private:
  std::string path_;
};

bool schema_of(const json& object) {  // a number or another name is not this format (value() would throw)
  const auto it = object.find("schema");
  return it != object.end() && it->is_string() && it->get<std::string>() == kSchema;
}

std::optional<std::string> room(const Reader& r, const json& j) {
  if (!j.contains("room")) return std::nullopt;
  const json& room = j["room"];
  if (room.is_string()) {
    if (room.get<std::string>() != "cornell-box") r.fail("room", "must be \"cornell-box\" or {\"file\": ...}");
    return std::nullopt;
  }
  r.only_keys(room, "room", {"file"});
  if (!room.contains("file")) r.fail("room.file", "missing");
  return r.file(room["file"], "room.file");
}

CompositionMesh mesh(const Reader& r, const json& m, const std::string& key) {
  r.only_keys(m, key, {"file", "rotate", "fit_into", "scale", "translate", "material", "two_sided"});
  if (!m.contains("file")) r.fail(key + ".file", "missing");
  CompositionMesh out;
  out.key = key;
  out.file = r.file(m["file"], key + ".file");
  if (m.contains("rotate")) {
    r.only_keys(m["rotate"], key + ".rotate", {"axis", "degrees"});
    out.rotate = CompositionRotate{r.triple(m["rotate"].value("axis", json()), key + ".rotate.axis"),
                                   r.number(m["rotate"].value("degrees", json()), key + ".rotate.degrees")};
  }
  if (m.contains("fit_into")) {
    if (m.contains("scale") || m.contains("translate")) r.fail(key + ".fit_into", "excludes scale and translate");
    r.only_keys(m["fit_into"], key + ".fit_into", {"min", "max"});
    out.fit_into = CompositionBox{r.triple(m["fit_into"].value("min", json()), key + ".fit_into.min"),
                                  r.triple(m["fit_into"].value("max", json()), key + ".fit_into.max")};
  }
  if (m.contains("scale")) out.scale = r.number(m["scale"], key + ".scale");
  if (m.contains("translate")) out.translate = r.triple(m["translate"], key + ".translate");
  if (m.contains("two_sided")) {
    if (!m["two_sided"].is_boolean()) r.fail(key + ".two_sided", "must be true or false");
    out.two_sided = m["two_sided"].get<bool>();
  }
  if (m.contains("material")) {
    r.only_keys(m["material"], key + ".material", {"reflectance", "emission"});
    CompositionMaterial material;
    material.reflectance =
        r.triple(m["material"].value("reflectance", json::array({0.5, 0.5, 0.5})), key + ".material.reflectance");
    if (m["material"].contains("emission")) material.emission = r.triple(m["material"]["emission"], key + ".material.emission");
    out.material = material;
  }
  return out;
}

CompositionLight light(const Reader& r, const json& l) {
  r.only_keys(l, "light", {"corners", "emission"});
  if (!l.contains("corners") || !l["corners"].is_array() || l["corners"].size() != 4) {
    r.fail("light.corners", "must be 4 corners, wound so that (c1 - c0) x (c2 - c0) faces the room");
  }
  CompositionLight out;
  for (std::size_t k = 0; k < 4; ++k) out.corners[k] = r.triple(l["corners"][k], "light.corners[" + std::to_string(k) + "]");
  out.emission = r.triple(l.value("emission", json()), "light.emission");
  return out;
}

CompositionCamera camera(const Reader& r, const json& c) {
  r.only_keys(c, "camera", {"position", "look_at", "up", "fov_deg"});
  if (!c.contains("position") || !c.contains("look_at")) r.fail("camera", "needs position and look_at");
  CompositionCamera out;
  out.position = r.triple(c["position"], "camera.position");
  out.look_at = r.triple(c["look_at"], "camera.look_at");
  if (c.contains("up")) out.up = r.triple(c["up"], "camera.up");
  if (c.contains("fov_deg")) out.fov_deg = r.number(c["fov_deg"], "camera.fov_deg");
  return out;
}

}  // namespace

CompositionFile parse_composition(std::string_view text, const std::string& path) {
  const json j = io::parse_json_text(text, path);  // depth, duplicate keys, comments, UTF-8, syntax
  const Reader r(path);
  r.only_keys(j, "(top level)", {"schema", "room", "meshes", "light", "camera"});
  if (!schema_of(j)) r.fail("schema", std::string("must be \"") + kSchema + "\"");
  CompositionFile out;
  out.room_file = room(r, j);
  const json meshes = j.value("meshes", json::array());
  if (!meshes.is_array()) r.fail("meshes", "must be an array");
  for (std::size_t i = 0; i < meshes.size(); ++i) out.meshes.push_back(mesh(r, meshes[i], "meshes[" + std::to_string(i) + "]"));
  if (j.contains("light")) out.light = light(r, j["light"]);
  if (j.contains("camera")) out.camera = camera(r, j["camera"]);
  return out;
}

bool has_composition_schema(std::string_view text, const std::string& path) {
  try {
    return schema_of(io::parse_json_text(text, path));
  } catch (const io::InputFileError&) {
    return false;
  }
}

}  // namespace rc::profiles
