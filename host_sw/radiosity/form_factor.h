// Patch-to-patch form factors: from the shooter's centre to a receiver's centre (point, disc), or
// from the receiver's centre to the shooter's whole triangle (analytic). docs/radiosity.md, step 4.
#pragma once

#include <array>
#include <cmath>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>

#include "io/choice.h"
#include "scenes/geometry.h"

namespace rc {

enum class FormFactorKind {
  PointToPoint,  // paper sec 2: cos.cos.A / (pi r^2); diverges as r -> 0
  Disc,          // the shooter as a disc of its area seen from the receiver: cos.cos.A / (pi r^2 + A)
  Analytic,      // exact from the receiver's centre to the shooter's triangle (contour integral); <= 1
};

}  // namespace rc

// The command-line and study names of the kinds, in enum order: the one list every option, study
// key and axis checks against (io/choice.h).
template <>
struct rc::ChoiceNames<rc::FormFactorKind> {
  static constexpr std::string_view what = "form factor";
  static constexpr std::array<std::string_view, 3> names = {"point", "disc", "analytic"};
};

namespace rc {

std::vector<std::string> form_factor_names();  // choice_names<FormFactorKind>()
// One of form_factor_names(); throws std::invalid_argument naming the value and the list.
FormFactorKind parse_form_factor_kind(const std::string& name);
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

// The exact form factor from a differential receiver (point `x`, unit normal `n`) to the triangle
// `shooter`, Lambert's contour integral F = (1/2pi) sum_i beta_i n . (R_i x R_i+1) / |R_i x R_i+1|
// (R_i = v_i - x, beta_i the angle between R_i and R_i+1) over the triangle clipped to x's front
// half-space (Sutherland-Hodgman against the tangent plane), so a shooter that crosses that plane
// counts only its visible part. The projected solid angle of anything in one hemisphere is at most
// pi, so F <= 1 (rounding clamped). Independent of the triangle's winding; 0 for a shooter wholly
// behind the plane or seen edge-on.
double point_to_triangle_form_factor(const Vec3& x, const Vec3& n, const Triangle& shooter);

// F from the receiver to the shooter (what shooting multiplies by), unoccluded: point and disc from
// the pair geometry alone. The analytic kind needs the shooter's triangle: point_to_triangle_form_factor.
inline double form_factor(FormFactorKind kind, const PairGeometry& g, double shooter_area) {
  if (!g.exchanges()) return 0.0;
  const double cc = g.cos_shooter * g.cos_receiver;
  const double pi = glm::pi<double>();
  switch (kind) {
    case FormFactorKind::PointToPoint:
      return cc * shooter_area / (pi * g.distance_squared);
    case FormFactorKind::Disc:
      return cc * shooter_area / (pi * g.distance_squared + shooter_area);
    case FormFactorKind::Analytic:
      break;  // needs the polygon
  }
  return 0.0;
}

// Every kind: the analytic one from the receiver's centre and normal to the shooter's triangle.
inline double form_factor(FormFactorKind kind, const PairGeometry& g, const Triangle& shooter, double shooter_area,
                          const Vec3& receiver_centre, const Vec3& receiver_normal) {
  if (kind != FormFactorKind::Analytic) return form_factor(kind, g, shooter_area);
  if (!g.exchanges()) return 0.0;
  return point_to_triangle_form_factor(receiver_centre, receiver_normal, shooter);
}

}  // namespace rc
