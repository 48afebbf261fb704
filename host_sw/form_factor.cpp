#include "host_sw/form_factor.h"

#include <glm/gtc/constants.hpp>
#include <stdexcept>

namespace rc {

FormFactorKind parse_form_factor_kind(const std::string& name) {
  if (name == "point") return FormFactorKind::PointToPoint;
  if (name == "disc") return FormFactorKind::Disc;
  throw std::invalid_argument("unknown form factor '" + name + "' (expected point or disc)");
}

std::string to_string(FormFactorKind kind) {
  return kind == FormFactorKind::PointToPoint ? "point" : "disc";
}

PairGeometry pair_geometry(const Vec3& shooter_centre, const Vec3& shooter_normal,
                           const Vec3& receiver_centre, const Vec3& receiver_normal) {
  const Vec3 d = receiver_centre - shooter_centre;
  const double r2 = glm::dot(d, d);
  if (r2 == 0) return {};
  const double r = std::sqrt(r2);
  return {glm::dot(shooter_normal, d) / r, -glm::dot(receiver_normal, d) / r, r2};
}

double form_factor(FormFactorKind kind, const PairGeometry& g, double shooter_area) {
  if (!g.exchanges()) return 0.0;
  const double cc = g.cos_shooter * g.cos_receiver;
  const double pi = glm::pi<double>();
  switch (kind) {
    case FormFactorKind::PointToPoint:
      return cc * shooter_area / (pi * g.distance_squared);
    case FormFactorKind::Disc:
      return cc * shooter_area / (pi * g.distance_squared + shooter_area);
  }
  return 0.0;
}

}  // namespace rc
