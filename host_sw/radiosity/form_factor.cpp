#include "host_sw/radiosity/form_factor.h"

#include <algorithm>
#include <stdexcept>

namespace rc {

std::vector<std::string> form_factor_names() { return choice_names<FormFactorKind>(); }

FormFactorKind parse_form_factor_kind(const std::string& name) { return parse_choice<FormFactorKind>(name); }

std::string to_string(FormFactorKind kind) { return choice_name(kind); }

namespace {

// A triangle clipped by one plane has at most 4 vertices.
struct ClippedPolygon {
  std::array<Vec3, 4> v;
  int size = 0;
};

// Sutherland-Hodgman against the half-space n . (p - x) >= 0; `p` relative to x already (R_i).
ClippedPolygon clip_to_front(const std::array<Vec3, 3>& r, const Vec3& n) {
  ClippedPolygon out;
  for (int i = 0; i < 3; ++i) {
    const Vec3& a = r[i];
    const Vec3& b = r[(i + 1) % 3];
    const double da = glm::dot(n, a), db = glm::dot(n, b);
    if (da >= 0) out.v[out.size++] = a;
    if ((da >= 0) != (db >= 0)) {
      const double t = da / (da - db);  // in [0, 1]: da and db differ in sign
      out.v[out.size++] = a + (b - a) * t;
    }
  }
  return out;
}

}  // namespace

double point_to_triangle_form_factor(const Vec3& x, const Vec3& n, const Triangle& shooter) {
  const ClippedPolygon p = clip_to_front({shooter.v0 - x, shooter.v1 - x, shooter.v2 - x}, n);
  if (p.size < 3) return 0.0;
  double sum = 0;
  for (int i = 0; i < p.size; ++i) {
    const Vec3& a = p.v[i];
    const Vec3& b = p.v[(i + 1) % p.size];
    const Vec3 c = glm::cross(a, b);
    const double length = glm::length(c);
    if (!(length > 0)) continue;  // an edge in line with x (or a vertex at x) subtends no angle
    const double beta = std::atan2(length, glm::dot(a, b));
    sum += beta * glm::dot(n, c) / length;
  }
  // The sign follows the winding as seen from x; the clipped polygon is convex and wholly in front,
  // so every winding gives the same magnitude.
  return std::min(1.0, std::fabs(sum) / (2 * glm::pi<double>()));
}

}  // namespace rc
