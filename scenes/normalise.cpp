#include "scenes/normalise.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace rc {

namespace {

void transform(Triangle& t, const Normalisation& n) {
  t.v0 = n.apply(t.v0);
  t.v1 = n.apply(t.v1);
  t.v2 = n.apply(t.v2);
}

// Dividing by the extent first makes the largest coordinate exactly 1.0 before it is scaled down.
Vec3 normalise_point(const Vec3& p, const Vec3& lo, double extent) {
  return (p - lo) / extent * kMaxNormalisedCoordinate;
}

}  // namespace

void normalise(Scene& scene) {
  Vec3 lo(std::numeric_limits<double>::infinity());
  Vec3 hi(-std::numeric_limits<double>::infinity());
  for (const Face& f : scene.faces) {
    for (const Vec3& v : {f.tri.v0, f.tri.v1, f.tri.v2}) {
      lo = glm::min(lo, v);
      hi = glm::max(hi, v);
    }
  }
  const Vec3 size = hi - lo;
  const double extent = std::max({size.x, size.y, size.z});
  if (!(extent > 0)) throw std::invalid_argument("scene '" + scene.name + "' has no extent");

  for (Face& f : scene.faces) {
    for (Vec3* v : {&f.tri.v0, &f.tri.v1, &f.tri.v2}) *v = normalise_point(*v, lo, extent);
  }
  const Normalisation step{lo, kMaxNormalisedCoordinate / extent};
  for (Patch& p : scene.patches) {
    transform(p.tri, step);
    p.centre = p.tri.centroid();
    p.area = p.tri.area();
  }
  scene.camera.position = step.apply(scene.camera.position);
  scene.camera.look_at = step.apply(scene.camera.look_at);
  // Compose with any earlier normalisation so world = offset + p / scale still holds.
  scene.normalisation.offset = scene.normalisation.offset + lo / scene.normalisation.scale;
  scene.normalisation.scale *= step.scale;
}

}  // namespace rc
