// Small geometric value types shared by every folder: a point/vector and a triangle.
#pragma once

#include <cmath>
#include <initializer_list>

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

// Exact rescaling, for checks and transforms that must not overflow or underflow at any finite
// scale (a scene at 1e200 squares its lengths to infinity, one at 1e-300 to zero). The exponent e of
// the largest coordinate magnitude (std::frexp's: every |coordinate| < 2^e; 0 when all are zero).
inline int magnitude_exponent(std::initializer_list<Vec3> points) {
  double largest = 0;
  for (const Vec3& p : points) largest = std::fmax(largest, std::fmax(std::fabs(p.x), std::fmax(std::fabs(p.y), std::fabs(p.z))));
  int exponent = 0;
  std::frexp(largest, &exponent);
  return exponent;
}

// p x 2^exponent, component by component: exact (no rounding) unless a result leaves the normal
// range, so every comparison of lengths and areas comes out as it would unscaled.
inline Vec3 scaled_by_power_of_two(const Vec3& p, int exponent) {
  return {std::ldexp(p.x, exponent), std::ldexp(p.y, exponent), std::ldexp(p.z, exponent)};
}

// The triangle scaled so that its largest coordinate magnitude lies in [0.5, 1).
inline Triangle scaled_to_unit(const Triangle& t) {
  const int e = -magnitude_exponent({t.v0, t.v1, t.v2});
  return {scaled_by_power_of_two(t.v0, e), scaled_by_power_of_two(t.v1, e), scaled_by_power_of_two(t.v2, e)};
}

inline bool is_finite(const Vec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

}  // namespace rc
