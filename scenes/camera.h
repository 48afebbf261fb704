// A pinhole camera (the Cornell Box data's camera by default).
#pragma once

#include "scenes/geometry.h"

namespace rc {

struct Camera {
  Vec3 position{278, 273, -800};
  Vec3 look_at{278, 273, 0};
  Vec3 up{0, 1, 0};
  double vertical_fov_deg = 39.3077;  // 2 atan(12.5 mm / 35 mm): the Cornell film and focal length
};

// The smallest sine of the angle between the up vector and the view direction that check_camera
// accepts. The picture's right vector is cross(view, up) normalised; computed from unit vectors its
// direction is off by about epsilon / sine, so at 1e-6 it is right to 2e-10 rad, while an up vector
// within 0.00006 degrees of the view is no choice anyone means.
constexpr double kMinCameraUpSine = 1e-6;

// The narrowest vertical field of view check_camera accepts, in degrees: 3.6 arc seconds, a telescope's
// view. Narrower, the projection's focal length 1 / tan(fov / 2) leaves the doubles' range for
// nothing anyone means (1e-300 degrees overflowed it and gave an all-black picture, exit 0).
constexpr double kMinFieldOfViewDeg = 1e-3;

// The one check of a camera, run wherever one is made (scene files, after normalisation, before
// rendering). Throws std::invalid_argument naming the problem (callers add the file and line):
// a coordinate that is not finite, the eye at the point looked at (no view direction), a zero up
// vector or one parallel to the view direction (within kMinCameraUpSine), or a vertical field of
// view outside [kMinFieldOfViewDeg, 180) degrees. Scale-free: a camera at 1e-300 or 1e200 is judged as at 1.
void check_camera(const Camera& camera);

// A camera that sees the whole of the box [lo, hi] (world units): it looks along +z at the box's
// centre, y up, with the Cornell camera's field of view, from as far as puts the box's bounding sphere
// inside the view (the Cornell Box's own view, from its open side, is of this kind). Throws
// std::invalid_argument for an empty or non-finite box.
Camera frame_bounds(const Vec3& lo, const Vec3& hi);

}  // namespace rc
