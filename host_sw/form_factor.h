// Patch-to-patch form factors from the shooter's centre to a receiver's centre.
#pragma once

#include <string>

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

PairGeometry pair_geometry(const Vec3& shooter_centre, const Vec3& shooter_normal,
                           const Vec3& receiver_centre, const Vec3& receiver_normal);

// F from the receiver to the shooter (what shooting multiplies by), unoccluded.
double form_factor(FormFactorKind kind, const PairGeometry& g, double shooter_area);

}  // namespace rc
