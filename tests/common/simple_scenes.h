// Small analytic scenes for tests.
#pragma once

#include <string>
#include <vector>

#include "scenes/normalise.h"
#include "scenes/prepare.h"
#include "scenes/scene_builder.h"
#include "scenes/subdivide.h"

namespace rc::test {

// The embedded Cornell Box: its own faces (face_target 0) or refined to face_target faces and each
// split into 4^face_levels, then every face into 4^patch_levels patches.
inline Scene cornell_box(int patch_levels, int face_target = 0, int face_levels = 0) {
  SceneOptions o;
  o.face_target = face_target;
  o.face_levels = face_levels;
  o.patch_levels = patch_levels;
  return prepare_scene(o).scene;
}

// Axis-aligned unit-square corners wound so that (v1-v0) x (v2-v0) = `normal` (an axis vector).
inline std::vector<Vec3> square(const Vec3& origin, const Vec3& a, const Vec3& b) {
  return {origin, origin + a, origin + a + b, origin + b};
}

// A closed cube [0,1]^3 whose 6 sides face inwards, all with the same emission and reflectance.
inline Scene furnace_box(double emission, double reflectance, int patch_levels) {
  SceneBuilder b("furnace");
  const int m = b.add_material({"grey", Spectrum::uniform(reflectance), Spectrum::uniform(emission)});
  const Vec3 x(1, 0, 0), y(0, 1, 0), z(0, 0, 1), o(0, 0, 0);
  b.add_surface("bottom", m, square(o, z, x), "test");  // z x x = +y
  b.add_surface("top", m, square(y, x, z), "test");     // x x z = -y
  b.add_surface("left", m, square(o, y, z), "test");    // y x z = +x
  b.add_surface("right", m, square(x, z, y), "test");   // z x y = -x
  b.add_surface("front", m, square(o, x, y), "test");   // x x y = +z
  b.add_surface("back", m, square(z, y, x), "test");    // y x x = -z
  Scene s = b.build();
  normalise(s);
  s.patches = make_patches(s.faces, patch_levels);
  return s;
}

}  // namespace rc::test
