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

}  // namespace rc
