#include "scenes/scene_builder.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace rc {

namespace {

// A triangle is degenerate when its area is negligible against its longest edge squared:
// the normal is then meaningless and it can neither emit nor block reliably. Judged on the triangle
// scaled exactly into [-1, 1)^3, so that a triangle at 1e200 or 1e-300 is judged as at 1.
bool is_degenerate(const Triangle& unscaled) {
  const Triangle t = scaled_to_unit(unscaled);
  const double longest = std::max({glm::length(t.v1 - t.v0), glm::length(t.v2 - t.v1),
                                   glm::length(t.v0 - t.v2)});
  return longest == 0.0 || glm::length(t.cross()) <= 1e-9 * longest * longest;
}

void check_spectrum(const std::string& material, const char* what, const Spectrum& s, double upper) {
  for (double v : s.band) {
    if (!(v >= 0.0) || !(v < upper)) {
      char range[96];
      std::snprintf(range, sizeof range, " %g is outside [0, %g)", v, upper);
      throw std::invalid_argument("material '" + material + "': " + what + range);
    }
  }
}

// The angle between the normals of a quad's two triangles (v0 v1 v2 and v0 v2 v3), in degrees:
// 0 for a planar quad, 180 for a bow tie. Computed on the quad scaled exactly into [-1, 1)^3.
double fold_degrees(const std::vector<Vec3>& v) {
  const int e = -magnitude_exponent({v[0], v[1], v[2], v[3]});
  Vec3 s[4];
  for (int i = 0; i < 4; ++i) s[i] = scaled_by_power_of_two(v[i], e);
  const Vec3 a = Triangle{s[0], s[1], s[2]}.normal(), b = Triangle{s[0], s[2], s[3]}.normal();
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)) * 180.0 / M_PI;
}

std::string format_degrees(double degrees) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", degrees);
  return text;
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
  for (const Vec3& v : vertices) {
    if (!is_finite(v)) throw std::invalid_argument(origin + ": surface '" + name + "' has a coordinate that is not finite");
  }
  if (vertices.size() == 4) check_planar(name, vertices, origin);
  const int surface = static_cast<int>(scene_.surface_names.size());
  scene_.surface_names.push_back(name);
  add_triangle({vertices[0], vertices[1], vertices[2]}, material, surface, origin);
  if (vertices.size() == 4) add_triangle({vertices[0], vertices[2], vertices[3]}, material, surface, origin);
}

void SceneBuilder::add_two_sided_surface(const std::string& name, int material, const std::vector<Vec3>& vertices,
                                         const std::string& origin) {
  add_surface(name, material, vertices, origin);
  std::vector<Vec3> back(vertices.rbegin(), vertices.rend());
  std::rotate(back.begin(), back.end() - 1, back.end());  // v0 first: the same split diagonal
  add_surface(name + " (back)", material, back, origin);
}

void add_back_faces(Scene& scene) {
  const std::size_t faces = scene.faces.size();
  std::size_t surfaces = scene.surface_names.size();
  for (const Face& f : scene.faces) surfaces = std::max(surfaces, static_cast<std::size_t>(f.surface) + 1);
  scene.surface_names.resize(surfaces, scene.name);  // a mesh's unnamed surfaces take its name
  for (std::size_t i = 0; i < surfaces; ++i) scene.surface_names.push_back(scene.surface_names[i] + " (back)");
  scene.faces.reserve(2 * faces);
  for (std::size_t f = 0; f < faces; ++f) {
    Face back = scene.faces[f];
    std::swap(back.tri.v1, back.tri.v2);
    back.surface += static_cast<int>(surfaces);
    scene.faces.push_back(back);
  }
}

void SceneBuilder::check_planar(const std::string& name, const std::vector<Vec3>& v, const std::string& origin) const {
  // A degenerate half is dropped with a warning (add_triangle); the other half is then planar.
  if (is_degenerate({v[0], v[1], v[2]}) || is_degenerate({v[0], v[2], v[3]})) return;
  const double fold = fold_degrees(v);
  if (fold <= kMaxQuadFoldDegrees) return;
  throw std::invalid_argument(origin + ": quad '" + name + "' is not planar: its triangles v0 v1 v2 and v0 v2 v3 " +
                              "are folded by " + format_degrees(fold) + " degrees along v0-v2 (at most " +
                              format_degrees(kMaxQuadFoldDegrees) + " allowed). Fix the vertices (their order: a " +
                              "bow tie folds by 180), or write the fold as two 'tri' lines if it is meant");
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

std::string Scene::surface_name(int surface) const {
  return surface >= 0 && surface < static_cast<int>(surface_names.size()) ? surface_names[surface] : std::string();
}

std::vector<Triangle> Scene::face_triangles() const {
  std::vector<Triangle> out;
  out.reserve(faces.size());
  for (const Face& f : faces) out.push_back(f.tri);
  return out;
}

}  // namespace rc
