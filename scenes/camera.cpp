#include "scenes/camera.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace rc {

namespace {

std::string text(const Vec3& v) {
  char out[96];
  std::snprintf(out, sizeof out, "(%g, %g, %g)", v.x, v.y, v.z);
  return out;
}

void check_finite(const Vec3& v, const char* what) {
  if (!is_finite(v)) throw std::invalid_argument(std::string("camera ") + what + " " + text(v) + " is not finite");
}

}  // namespace

void check_camera(const Camera& c) {
  check_finite(c.position, "position");
  check_finite(c.look_at, "look-at point");
  check_finite(c.up, "up vector");
  if (!(c.vertical_fov_deg >= kMinFieldOfViewDeg && c.vertical_fov_deg < 180)) {
    char fov[128];
    std::snprintf(fov, sizeof fov, "%g degrees is outside [%g, 180) (kMinFieldOfViewDeg: narrower views leave the "
                  "projection's range)", c.vertical_fov_deg, kMinFieldOfViewDeg);
    throw std::invalid_argument(std::string("camera vertical field of view ") + fov);
  }
  // Directions are compared after exact power-of-two scaling, so no length overflows or vanishes.
  const int e = -magnitude_exponent({c.position, c.look_at});
  const Vec3 view = scaled_by_power_of_two(c.look_at, e) - scaled_by_power_of_two(c.position, e);
  if (view == Vec3(0.0)) {
    throw std::invalid_argument("camera looks at its own position " + text(c.position) + " (no view direction)");
  }
  if (c.up == Vec3(0.0)) throw std::invalid_argument("camera up vector is zero");
  const Vec3 up = glm::normalize(scaled_by_power_of_two(c.up, -magnitude_exponent({c.up})));
  const double sine = glm::length(glm::cross(glm::normalize(view), up));
  if (!(sine >= kMinCameraUpSine)) {
    throw std::invalid_argument("camera up vector " + text(c.up) + " is parallel to the view direction " +
                                text(c.look_at - c.position) + " (the picture would have no up); choose an up "
                                "vector across the view");
  }
}

Camera frame_bounds(const Vec3& lo, const Vec3& hi) {
  const Vec3 extent = hi - lo;
  if (!(std::isfinite(extent.x) && std::isfinite(extent.y) && std::isfinite(extent.z)) ||
      !(extent.x >= 0 && extent.y >= 0 && extent.z >= 0) || !(glm::length(extent) > 0)) {
    throw std::invalid_argument("frame_bounds: the scene's bounds are empty or not finite");
  }
  Camera c;
  const Vec3 centre = lo + 0.5 * extent;
  const double radius = 0.5 * glm::length(extent);
  const double half_fov = 0.5 * c.vertical_fov_deg * 3.14159265358979323846 / 180.0;
  c.look_at = centre;
  c.position = centre - Vec3(0, 0, radius / std::sin(half_fov));
  c.up = Vec3(0, 1, 0);
  return c;
}

}  // namespace rc
