// Turns surfaces (quads or triangles with a material) into faces, whether they come from the
// embedded Cornell Box or from a scene file. Zero-area faces are dropped and reported.
#pragma once

#include <string>
#include <vector>

#include "scenes/scene.h"

namespace rc {

class SceneBuilder {
 public:
  explicit SceneBuilder(std::string scene_name);

  // Returns the material's index; throws std::invalid_argument on a duplicate or bad value.
  int add_material(const Material& material);
  // Index of a material by name, or -1.
  int find_material(const std::string& name) const;
  // A quad (4 vertices, split along v0-v2) or a triangle (3 vertices). `origin` names where the
  // surface came from (e.g. "box.scene:12") for warnings. Winding: (v1-v0) x (v2-v0) is the front.
  void add_surface(const std::string& name, int material, const std::vector<Vec3>& vertices,
                   const std::string& origin);
  void set_camera(const Camera& camera) { scene_.camera = camera; }

  const std::vector<std::string>& warnings() const { return warnings_; }
  // The scene with faces only (no patches yet, not normalised).
  Scene build() const;

 private:
  void add_triangle(const Triangle& tri, int material, int surface, const std::string& origin);

  Scene scene_;
  std::vector<std::string> warnings_;
};

}  // namespace rc
