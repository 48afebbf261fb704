// Small geometric value types shared by every folder: a point/vector and a triangle.
#pragma once

#include <glm/glm.hpp>

namespace rc {

// Double precision throughout the host side; the hardware's fixed-point view lives in pipeline/.
using Vec3 = glm::dvec3;

struct Triangle {
  Vec3 v0, v1, v2;

  Vec3 edge1() const { return v1 - v0; }
  Vec3 edge2() const { return v2 - v0; }
  // Unnormalised normal, (v1 - v0) x (v2 - v0); its length is twice the area.
  Vec3 cross() const { return glm::cross(edge1(), edge2()); }
  double area() const { return 0.5 * glm::length(cross()); }
  Vec3 normal() const { return glm::normalize(cross()); }
  Vec3 centroid() const { return (v0 + v1 + v2) / 3.0; }
};

}  // namespace rc
