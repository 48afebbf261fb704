// Turns surfaces (quads or triangles with a material) into faces, whether they come from the
// embedded Cornell Box or from a scene file. Zero-area faces are dropped and reported.
#pragma once

#include <string>
#include <vector>

#include "scenes/scene.h"

namespace rc {

// How far a quad's two triangles may be folded against each other, in degrees, before the quad is
// refused as not planar. A quad is a planar polygon: data measured from a real object are not quite
// (the Cornell Box's red wall is folded by 0.47 degrees), but a larger fold is a mistake in the
// vertices (wrong order makes a bow tie, 180 degrees) or a shape that should be two triangles. A fold
// that closes onto itself ruins the solution: beyond about 100 degrees the point form factor across
// it exceeds 1 at every patch size and the solve diverges (docs/scenes.md). 5 degrees is ten times
// the Cornell data's fold and far below that.
constexpr double kMaxQuadFoldDegrees = 5.0;

// Makes every face of `scene` two-sided: after the faces, each face's back (its vertices v0 v2 v1,
// the same material) on a surface "NAME (back)" per surface. find_sheets then pairs them up.
void add_back_faces(Scene& scene);

class SceneBuilder {
 public:
  explicit SceneBuilder(std::string scene_name);

  // Returns the material's index; throws std::invalid_argument on a duplicate or bad value.
  int add_material(const Material& material);
  // Index of a material by name, or -1.
  int find_material(const std::string& name) const;
  // A quad (4 vertices, split along v0-v2) or a triangle (3 vertices). `origin` names where the
  // surface came from (e.g. "box.scene:12") for warnings and errors. Winding: (v1-v0) x (v2-v0) is
  // the front. Throws std::invalid_argument (starting with `origin`) for a coordinate that is not
  // finite or a quad folded by more than kMaxQuadFoldDegrees.
  void add_surface(const std::string& name, int material, const std::vector<Vec3>& vertices,
                   const std::string& origin);
  // A surface lit from both sides: the surface, then its back, surface "NAME (back)" with the same
  // material and the vertices v0 then the rest reversed (v0 v3 v2 v1, or v0 v2 v1), whose triangles
  // are the front's with the winding turned. find_sheets makes each pair one sheet (scenes/sheets.h).
  void add_two_sided_surface(const std::string& name, int material, const std::vector<Vec3>& vertices,
                             const std::string& origin);
  void set_camera(const Camera& camera) {
    scene_.camera = camera;
    scene_.camera_given = true;
  }

  const std::vector<std::string>& warnings() const { return warnings_; }
  std::size_t face_count() const { return scene_.faces.size(); }
  // The scene with faces only (no patches yet, not normalised).
  Scene build() const;

 private:
  void add_triangle(const Triangle& tri, int material, int surface, const std::string& origin);
  void check_planar(const std::string& name, const std::vector<Vec3>& vertices, const std::string& origin) const;

  Scene scene_;
  std::vector<std::string> warnings_;
};

}  // namespace rc
