#include "scenes/normalise.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
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

void scale(Triangle& t, int exponent) {
  for (Vec3* v : {&t.v0, &t.v1, &t.v2}) *v = scaled_by_power_of_two(*v, exponent);
}

}  // namespace

void rescale_by_power_of_two(Scene& scene) {
  double largest = 0;
  for (std::size_t i = 0; i < scene.faces.size(); ++i) {
    const Triangle& t = scene.faces[i].tri;
    if (!is_finite(t.v0) || !is_finite(t.v1) || !is_finite(t.v2)) {
      throw std::invalid_argument("scene '" + scene.name + "': face " + std::to_string(i) +
                                  " has a coordinate that is not finite");
    }
    for (const Vec3& v : {t.v0, t.v1, t.v2}) largest = std::max({largest, std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
  }
  const int exponent = -magnitude_exponent({Vec3(largest)});
  if (exponent == 0) return;  // already in [0.5, 1), or no coordinate but 0
  for (Face& f : scene.faces) scale(f.tri, exponent);
  for (Patch& p : scene.patches) {
    scale(p.tri, exponent);
    p.centre = scaled_by_power_of_two(p.centre, exponent);
    p.area = std::ldexp(p.area, 2 * exponent);
  }
  scene.camera.position = scaled_by_power_of_two(scene.camera.position, exponent);
  scene.camera.look_at = scaled_by_power_of_two(scene.camera.look_at, exponent);
  // world = offset + p / scale still holds with p scaled by 2^exponent.
  scene.normalisation.scale = std::ldexp(scene.normalisation.scale, exponent);
}

void normalise(Scene& scene) {
  rescale_by_power_of_two(scene);  // every |coordinate| < 1 now: no difference below overflows
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
  const Normalisation step{lo, kMaxNormalisedCoordinate / extent};
  const double scale = scene.normalisation.scale * step.scale;
  // The normalisation is recorded as world = offset + p / scale; a scene smaller than DBL_MIN has
  // subnormal coordinates (fewer than 53 bits) and a scale beyond the doubles.
  if (!(scale <= 1.0 / DBL_MIN)) {
    char text[160];
    std::snprintf(text, sizeof text, "' is %g across, smaller than the smallest normal double (%g): its coordinates "
                  "have lost precision; scale it up", extent / scene.normalisation.scale, DBL_MIN);
    throw std::invalid_argument("scene '" + scene.name + text);
  }

  for (Face& f : scene.faces) {
    for (Vec3* v : {&f.tri.v0, &f.tri.v1, &f.tri.v2}) *v = normalise_point(*v, lo, extent);
  }
  // The loaders drop faces without area; a face that has none now was lost to the doubles
  // themselves (a room beside a mesh 1e300 away), and would emit or block nothing.
  std::size_t lost = 0, first = 0;
  for (std::size_t i = 0; i < scene.faces.size(); ++i) {
    if (scene.faces[i].tri.area() > 0) continue;
    if (lost++ == 0) first = i;
  }
  if (lost > 0) {
    throw std::invalid_argument("scene '" + scene.name + "': " + std::to_string(lost) + " of " +
                                std::to_string(scene.faces.size()) + " faces (the first: face " + std::to_string(first) +
                                ") have no area once the scene is scaled into the unit cube: its parts differ in size "
                                "by more than double precision holds; bring them closer together");
  }
  for (Patch& p : scene.patches) {
    transform(p.tri, step);
    p.centre = p.tri.centroid();
    p.area = p.tri.area();
  }
  scene.camera.position = step.apply(scene.camera.position);
  scene.camera.look_at = step.apply(scene.camera.look_at);
  // Compose with any earlier normalisation so world = offset + p / scale still holds.
  scene.normalisation.offset = scene.normalisation.offset + lo / scene.normalisation.scale;
  scene.normalisation.scale = scale;
  try {
    check_camera(scene.camera);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("scene '" + scene.name + "', once normalised: " + e.what());
  }
}

}  // namespace rc
