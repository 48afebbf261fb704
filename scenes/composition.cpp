#include "scenes/composition.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <utility>

#include <glm/gtc/matrix_transform.hpp>

#include "io/input_file.h"
#include "profiles/composition_file.h"
#include "scenes/cornell_box.h"
#include "scenes/mesh_import.h"
#include "scenes/scene_builder.h"
#include "scenes/scene_source.h"

namespace rc {

namespace {

using profiles::CompositionFile;
using profiles::CompositionMesh;

// "<path>: <key>: <problem>", as the edge names its own errors.
[[noreturn]] void fail(const std::string& path, const std::string& key, const std::string& problem) {
  throw SceneFileError(path + ": " + key + ": " + problem);
}

Vec3 vec3(const profiles::Triple& t) { return Vec3(t[0], t[1], t[2]); }

// Components in [0, below).
Spectrum spectrum(const std::string& path, const profiles::Triple& v, const std::string& key, double below) {
  Spectrum s;
  for (std::size_t b = 0; b < kBands; ++b) {
    const double x = v[b];
    if (x < 0 || x >= below) fail(path, key, "components must be at least 0 and below " + std::to_string(below));
    s.band[b] = x;
  }
  return s;
}

LoadedScene load_room(const std::string& path, const CompositionFile& c) {
  if (!c.room_file) return {cornell_box(), {}};
  const std::string& file = *c.room_file;
  const SceneSource source = read_scene_source(file);  // read once; a FIFO or device is refused by name
  if (source.format == SceneFormat::composition) fail(path, "room.file", file + " is a composition; compositions do not nest (name its room or meshes here)");
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
std::vector<Face> place(const std::string& path, const CompositionMesh& m, std::vector<Face> faces) {
  const std::string& key = m.key;
  Box box;
  for (const Face& f : faces)
    for (const Vec3& v : {f.tri.v0, f.tri.v1, f.tri.v2}) box.add(v);
  const Vec3 centre = (box.lo + box.hi) * 0.5;
  glm::dmat4 rotation(1.0);
  if (m.rotate) {
    const Vec3 axis = vec3(m.rotate->axis);
    if (glm::length(axis) == 0) fail(path, key + ".rotate.axis", "must not be zero");
    rotation = glm::rotate(glm::dmat4(1.0), glm::radians(m.rotate->degrees), glm::normalize(axis));
  }
  auto rotated = [&](const Vec3& p) { return Vec3(rotation * glm::dvec4(p - centre, 1.0)); };
  Box turned;
  for (const Face& f : faces)
    for (const Vec3& v : {f.tri.v0, f.tri.v1, f.tri.v2}) turned.add(rotated(v));

  double scale = 1;
  Vec3 offset = centre;
  if (m.fit_into) {
    const Vec3 lo = vec3(m.fit_into->min);
    const Vec3 hi = vec3(m.fit_into->max);
    if (!(hi.x > lo.x && hi.y > lo.y && hi.z > lo.z)) fail(path, key + ".fit_into", "max must exceed min on every axis");
    const Vec3 size = turned.hi - turned.lo;
    scale = std::numeric_limits<double>::max();
    for (int i = 0; i < 3; ++i) {
      if (size[i] > 0) scale = std::min(scale, (hi[i] - lo[i]) / size[i]);
    }
    // Centred in the box, resting on its floor (min y).
    const Vec3 mid = (turned.lo + turned.hi) * 0.5;
    offset = Vec3((lo.x + hi.x) / 2, lo.y, (lo.z + hi.z) / 2) - Vec3(mid.x, turned.lo.y, mid.z) * scale;
  } else {
    if (m.scale) {
      scale = *m.scale;
      if (!(scale > 0)) fail(path, key + ".scale", "must be positive");
    }
    offset = centre * 1.0;
    if (m.translate) offset += vec3(*m.translate);
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

bool is_composition_file(const std::string& path) {
  try {
    const SceneSource source = read_scene_source(path);
    return source.format == SceneFormat::composition && profiles::has_composition_schema(source.bytes, path);
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

namespace {

CompositionFile parse(const std::string& text, const std::string& path) {
  try {
    return profiles::parse_composition(text, path);
  } catch (const profiles::CompositionError& e) {  // starts with the file and the key
    throw SceneFileError(e.what());
  } catch (const io::InputFileError& e) {  // the text (io/json_text.h)
    throw SceneFileError(e.what());
  }
}

void add_mesh(LoadedScene& out, const std::string& path, const CompositionMesh& m) {
  const std::string& key = m.key;
  MeshImportOptions o;
  o.require_emitter = false;
  // Assimp would say only "No suitable reader found" for our own formats.
  const SceneFormat format = read_scene_source(m.file).format;
  if (format == SceneFormat::composition) fail(path, key + ".file", m.file + " is a composition; compositions do not nest (name its meshes here)");
  if (format == SceneFormat::text) fail(path, key + ".file", m.file + " is a text scene; a mesh must be a mesh file (OBJ, PLY, OFF, STL, ...), or use it as the room");
  LoadedScene mesh = import_mesh_file(m.file, o);
  mesh.scene.faces = place(path, m, std::move(mesh.scene.faces));
  if (m.two_sided) add_back_faces(mesh.scene);  // thin shells: leaves, paper, plates
  Material override_material;
  if (m.material) {
    override_material.name = mesh.scene.name + " (override)";
    override_material.reflectance = spectrum(path, m.material->reflectance, key + ".material.reflectance", 1.0);
    if (m.material->emission) override_material.emission = spectrum(path, *m.material->emission, key + ".material.emission", 1e300);
  }
  out.warnings.insert(out.warnings.end(), mesh.warnings.begin(), mesh.warnings.end());
  append(out.scene, std::move(mesh.scene), m.material ? &override_material : nullptr);
}

void add_light(LoadedScene& out, const std::string& path, const profiles::CompositionLight& l) {
  std::vector<Vec3> c;
  for (const profiles::Triple& corner : l.corners) c.push_back(vec3(corner));
  // Through the builder, as every surface: a folded quad is an error, a zero-area half a warning.
  SceneBuilder light("light");
  const int material = light.add_material({"light", Spectrum{}, spectrum(path, l.emission, "light.emission", 1e300)});
  try {
    light.add_surface("light", material, c, path + ": light.corners");
  } catch (const std::invalid_argument& e) {
    throw SceneFileError(e.what());  // starts with the file and the key
  }
  if (light.face_count() == 0) fail(path, "light.corners", "the light has no area");
  out.warnings.insert(out.warnings.end(), light.warnings().begin(), light.warnings().end());
  append(out.scene, light.build(), nullptr);
}

}  // namespace

LoadedScene load_composition_text(const std::string& text, const std::string& path) {
  const CompositionFile c = parse(text, path);
  LoadedScene out = load_room(path, c);
  out.scene.name = std::filesystem::path(path).filename().string();
  for (const CompositionMesh& m : c.meshes) add_mesh(out, path, m);
  if (c.light) add_light(out, path, *c.light);
  if (c.camera) {
    Camera cam;
    cam.position = Vec3(c.camera->position[0], c.camera->position[1], c.camera->position[2]);
    cam.look_at = Vec3(c.camera->look_at[0], c.camera->look_at[1], c.camera->look_at[2]);
    cam.up = Vec3(c.camera->up[0], c.camera->up[1], c.camera->up[2]);
    if (c.camera->fov_deg) cam.vertical_fov_deg = *c.camera->fov_deg;
    try {
      check_camera(cam);
    } catch (const std::invalid_argument& e) {
      fail(path, "camera", e.what());
    }
    out.scene.camera = cam;
    out.scene.camera_given = true;
  }
  if (out.scene.faces.empty()) fail(path, "(top level)", "the composed scene has no faces");
  if (!out.scene.emits_light()) fail(path, "light", "nothing in the composed scene emits light: add a light or an emissive material");
  return out;
}

}  // namespace rc
