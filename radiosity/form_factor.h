// Patch-to-patch form factors from the shooter's centre to a receiver's centre.
#pragma once

#include <cmath>
#include <string>

#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>

#include "scenes/geometry.h"

namespace rc {

enum class FormFactorKind {
  PointToPoint,  // paper sec 2: cos.cos.A / (pi r^2); diverges as r -> 0
  Disc,          // the shooter as a disc of its area seen from the receiver: cos.cos.A / (pi r^2 + A)
};

FormFactorKind parse_form_factor_kind(const std::string& name);  // "point" or "disc"
std::string to_string(FormFactorKind kind);

// The geometry of one shooter-receiver pair. Receivers behind the shooter or facing away from it
// (either cosine not positive) exchange no energy and get no visibility segment.
struct PairGeometry {
  double cos_shooter = 0;
  double cos_receiver = 0;
  double distance_squared = 0;
  bool exchanges() const { return cos_shooter > kMinCosine && cos_receiver > kMinCosine; }

  // Coplanar patches come out at cos ~ 1e-17 from rounding; treat anything this small as zero.
  static constexpr double kMinCosine = 1e-9;
};

// Inline: the solver calls both once per receiver per step.
inline PairGeometry pair_geometry(const Vec3& shooter_centre, const Vec3& shooter_normal,
                                  const Vec3& receiver_centre, const Vec3& receiver_normal) {
  const Vec3 d = receiver_centre - shooter_centre;
  const double r2 = glm::dot(d, d);
  if (r2 == 0) return {};
  const double r = std::sqrt(r2);
  return {glm::dot(shooter_normal, d) / r, -glm::dot(receiver_normal, d) / r, r2};
}

// F from the receiver to the shooter (what shooting multiplies by), unoccluded.
inline double form_factor(FormFactorKind kind, const PairGeometry& g, double shooter_area) {
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
