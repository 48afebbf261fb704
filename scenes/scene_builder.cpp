#include "scenes/scene_builder.h"

#include <algorithm>
#include <stdexcept>

namespace rc {

namespace {

// A triangle is degenerate when its area is negligible against its longest edge squared:
// the normal is then meaningless and it can neither emit nor block reliably.
bool is_degenerate(const Triangle& t) {
  const double longest = std::max({glm::length(t.v1 - t.v0), glm::length(t.v2 - t.v1),
                                   glm::length(t.v0 - t.v2)});
  return longest == 0.0 || glm::length(t.cross()) <= 1e-9 * longest * longest;
}

void check_spectrum(const std::string& material, const char* what, const Spectrum& s, double upper) {
  for (double v : s.band) {
    if (!(v >= 0.0) || !(v < upper)) {
      throw std::invalid_argument("material '" + material + "': " + what + " " + std::to_string(v) +
                                  " is outside [0, " + (upper > 1e300 ? std::string("inf") : std::to_string(upper)) + ")");
    }
  }
}

}  // namespace

SceneBuilder::SceneBuilder(std::string scene_name) { scene_.name = std::move(scene_name); }

int SceneBuilder::add_material(const Material& material) {
  if (material.name.empty()) throw std::invalid_argument("material without a name");
  if (find_material(material.name) >= 0) {
    throw std::invalid_argument("material '" + material.name + "' is defined twice");
  }
  // Reflectance 1 would never converge (energy is never absorbed).
  check_spectrum(material.name, "reflectance", material.reflectance, 1.0);
  check_spectrum(material.name, "emission", material.emission, 1e308);
  scene_.materials.push_back(material);
  return static_cast<int>(scene_.materials.size()) - 1;
}

int SceneBuilder::find_material(const std::string& name) const {
  for (std::size_t i = 0; i < scene_.materials.size(); ++i) {
    if (scene_.materials[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

void SceneBuilder::add_surface(const std::string& name, int material,
                               const std::vector<Vec3>& vertices, const std::string& origin) {
  if (material < 0 || material >= static_cast<int>(scene_.materials.size())) {
    throw std::invalid_argument(origin + ": surface '" + name + "' has no valid material");
  }
  if (vertices.size() != 3 && vertices.size() != 4) {
    throw std::invalid_argument(origin + ": a surface needs 3 or 4 vertices");
  }
  const int surface = static_cast<int>(scene_.surface_names.size());
  scene_.surface_names.push_back(name);
  add_triangle({vertices[0], vertices[1], vertices[2]}, material, surface, origin);
  if (vertices.size() == 4) add_triangle({vertices[0], vertices[2], vertices[3]}, material, surface, origin);
}

void SceneBuilder::add_triangle(const Triangle& tri, int material, int surface,
                                const std::string& origin) {
  if (is_degenerate(tri)) {
    warnings_.push_back(origin + ": zero-area triangle of surface '" + scene_.surface_names[surface] +
                        "' dropped");
    return;
  }
  scene_.faces.push_back({tri, material, surface});
}

Scene SceneBuilder::build() const {
  if (scene_.faces.empty()) throw std::invalid_argument("scene '" + scene_.name + "' has no faces");
  return scene_;
}

bool Scene::emits_light() const {
  return std::any_of(faces.begin(), faces.end(), [&](const Face& f) { return materials[f.material].emits(); });
}

std::vector<Triangle> Scene::face_triangles() const {
  std::vector<Triangle> out;
  out.reserve(faces.size());
  for (const Face& f : faces) out.push_back(f.tri);
  return out;
}

}  // namespace rc
