// The analytic (point-to-polygon, contour-integral) form factor against independent oracles: closed
// forms for a disc and a square on the axis and a rectangle at a corner, numerical integration of
// the kernel cos.cos / (pi r^2) over a shooter (also one that crosses the receiver's plane), the
// exact unit-square cases of shared/data/cornell-box.md, and metamorphic checks (rotation, winding,
// splitting the polygon), plus F <= 1 on random configurations.
#include <gtest/gtest.h>

#include <random>

#include <glm/gtc/constants.hpp>

#include "host_sw/radiosity/form_factor.h"
#include "scenes/subdivide.h"

namespace rc {
namespace {

const double kPi = glm::pi<double>();

double analytic(const Vec3& x, const Vec3& n, const Triangle& t) { return point_to_triangle_form_factor(x, n, t); }

// The square [-s, s]^2 at height h above the origin (two triangles), seen from the origin facing +z.
double square_on_axis(double s, double h) {
  const Vec3 a(-s, -s, h), b(s, -s, h), c(s, s, h), d(-s, s, h);
  const Vec3 x(0, 0, 0), n(0, 0, 1);
  return analytic(x, n, {a, b, c}) + analytic(x, n, {a, c, d});
}

// Differential element to a parallel rectangle a x b at height h whose corner lies on the element's
// normal (Howell's catalogue, B-3): F = 1/(2 pi) [A/sqrt(1+A^2) atan(B/sqrt(1+A^2)) + (A <-> B)].
double corner_rectangle_exact(double a, double b, double h) {
  const double A = a / h, B = b / h;
  const double sa = std::sqrt(1 + A * A), sb = std::sqrt(1 + B * B);
  return (A / sa * std::atan(B / sa) + B / sb * std::atan(A / sb)) / (2 * kPi);
}

// F from (x, n) to `t` by the midpoint rule over 4^levels sub-triangles: sum of
// max(0, cos_r) |cos_s| dA / (pi r^2). An oracle that shares nothing with the contour integral.
double integrated(const Vec3& x, const Vec3& n, const Triangle& t, int levels) {
  std::vector<Face> face{{t}};
  double f = 0;
  for (const Patch& p : make_patches(face, levels)) {
    const Vec3 d = p.centre - x;
    const double r2 = glm::dot(d, d);
    const double cos_r = glm::dot(n, d) / std::sqrt(r2);
    const double cos_s = std::fabs(glm::dot(p.normal, d)) / std::sqrt(r2);
    if (cos_r > 0) f += cos_r * cos_s * p.area / (kPi * r2);
  }
  return f;
}

TEST(AnalyticFormFactor, PointOnTheAxisOfARegularPolygonApproachesTheDisc) {
  const double R = 1.0, h = 0.5, disc = R * R / (R * R + h * h);
  const int sides = 4096;
  double f = 0, area = 0;
  for (int k = 0; k < sides; ++k) {
    const double a0 = 2 * kPi * k / sides, a1 = 2 * kPi * (k + 1) / sides;
    const Triangle t{{0, 0, h}, {R * std::cos(a0), R * std::sin(a0), h}, {R * std::cos(a1), R * std::sin(a1), h}};
    f += analytic({0, 0, 0}, {0, 0, 1}, t);
    area += t.area();
  }
  // The polygon's area falls short of the disc's by (pi R^2 - area); its F by about as much relatively.
  const double deficit = (kPi * R * R - area) / (kPi * R * R);
  std::printf("4096-gon on axis: %.12f disc %.12f (area deficit %.2e)\n", f, disc, deficit);
  EXPECT_LT(f, disc);
  EXPECT_NEAR(f, disc, 2 * deficit);
}

TEST(AnalyticFormFactor, ASquareOnTheAxisAndARectangleAtACornerMatchTheirClosedForms) {
  for (double s : {0.1, 0.5, 1.0, 3.0}) {
    const double S = s / 1.0;
    const double exact = 4 / kPi * S / std::sqrt(1 + S * S) * std::atan(S / std::sqrt(1 + S * S));
    EXPECT_NEAR(square_on_axis(s, 1.0), exact, 1e-14) << s;
    EXPECT_NEAR(square_on_axis(s, 1.0), 4 * corner_rectangle_exact(s, s, 1.0), 1e-14) << s;
  }
  // A rectangle 2 x 0.7 at height 0.4 with a corner above the receiver.
  const Vec3 a(0, 0, 0.4), b(2, 0, 0.4), c(2, 0.7, 0.4), d(0, 0.7, 0.4);
  const double f = analytic({0, 0, 0}, {0, 0, 1}, {a, b, c}) + analytic({0, 0, 0}, {0, 0, 1}, {a, c, d});
  EXPECT_NEAR(f, corner_rectangle_exact(2, 0.7, 0.4), 1e-14);
  EXPECT_NEAR(square_on_axis(1e6, 1.0), 1.0, 1e-9);  // a huge square fills the hemisphere
}

// Integrates the point formula over the receiver square (midpoint rule, m x m points): the exact
// patch-to-patch values of the data sheet, 0.19982 (parallel) and 0.20004 (perpendicular).
double square_to_square(const Vec3& origin, const Vec3& u, const Vec3& v, const Vec3& n, const Triangle (&shooter)[2], int m) {
  double f = 0;
  for (int i = 0; i < m; ++i) {
    for (int k = 0; k < m; ++k) {
      const Vec3 x = origin + u * ((i + 0.5) / m) + v * ((k + 0.5) / m);
      f += analytic(x, n, shooter[0]) + analytic(x, n, shooter[1]);
    }
  }
  return f / (m * m);
}

TEST(AnalyticFormFactor, IntegratedOverAReceiverSquareItGivesTheDataSheetsExactValues) {
  const Triangle top[2] = {{{0, 0, 1}, {1, 1, 1}, {1, 0, 1}}, {{0, 0, 1}, {0, 1, 1}, {1, 1, 1}}};
  const double parallel = square_to_square({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, top, 64);
  const Triangle wall[2] = {{{0, 0, 0}, {0, 1, 0}, {0, 1, 1}}, {{0, 0, 0}, {0, 1, 1}, {0, 0, 1}}};
  const double perpendicular = square_to_square({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, wall, 256);
  std::printf("analytic, integrated over the receiver: parallel %.6f (exact 0.19982), perpendicular %.6f (0.20004)\n",
              parallel, perpendicular);
  EXPECT_NEAR(parallel, 0.19982, 2e-5);       // midpoint rule, smooth integrand: error ~1e-5 at 64^2
  EXPECT_NEAR(perpendicular, 0.20004, 5e-4);  // the shared edge's log singularity converges slowly
}

TEST(AnalyticFormFactor, AShooterThatCrossesTheReceiversPlaneCountsOnlyItsFrontPart) {
  // The receiver at the origin faces +z; the triangle runs from z = -0.6 to z = +0.9, tilted.
  const Vec3 x(0, 0, 0), n(0, 0, 1);
  const Triangle t{{0.8, -0.5, -0.6}, {1.1, 0.6, 0.9}, {0.5, 0.4, 0.3}};
  const double f = analytic(x, n, t);
  const double reference = integrated(x, n, t, 8);  // 65,536 sub-triangles
  std::printf("straddling: analytic %.8f integrated %.8f\n", f, reference);
  EXPECT_GT(f, 0.01);
  EXPECT_NEAR(f, reference, 2e-4 * reference);
  // Unclipped, the part behind the plane would subtract: the clip is what makes this right.
  const Triangle whole_front{{0.8, -0.5, 0.6}, {1.1, 0.6, 0.9}, {0.5, 0.4, 0.3}};
  EXPECT_NEAR(analytic(x, n, whole_front), integrated(x, n, whole_front, 8), 2e-4 * analytic(x, n, whole_front));
  // Wholly behind: nothing; edge-on: nothing.
  EXPECT_EQ(analytic(x, n, {{1, 0, -1}, {2, 0, -1}, {1, 1, -2}}), 0.0);
  EXPECT_EQ(analytic(x, n, {{1, 0, 1}, {2, 0, 1}, {3, 0, 2}}), 0.0);
}

glm::dmat3 random_rotation(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  const Vec3 a = glm::normalize(Vec3(g(rng), g(rng), g(rng)));
  Vec3 b = Vec3(g(rng), g(rng), g(rng));
  b = glm::normalize(b - a * glm::dot(a, b));
  return glm::dmat3(a, b, glm::cross(a, b));
}

struct Configuration {
  Vec3 x, n;
  Triangle t;
};

Configuration random_configuration(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  std::normal_distribution<double> g;
  auto point = [&] { return Vec3(u(rng), u(rng), u(rng)); };
  return {point() * 0.1, glm::normalize(Vec3(g(rng), g(rng), g(rng))), {point(), point(), point()}};
}

TEST(AnalyticFormFactor, RotationWindingAndSplittingChangeNothing) {
  std::mt19937_64 rng(23);
  for (int i = 0; i < 2000; ++i) {
    const Configuration c = random_configuration(rng);
    const double f = analytic(c.x, c.n, c.t);
    const glm::dmat3 q = random_rotation(rng);
    const Vec3 shift(3.5, -2.25, 0.75);
    const double rotated = analytic(q * c.x + shift, q * c.n, {q * c.t.v0 + shift, q * c.t.v1 + shift, q * c.t.v2 + shift});
    EXPECT_NEAR(rotated, f, 1e-12) << i;
    EXPECT_NEAR(analytic(c.x, c.n, {c.t.v0, c.t.v2, c.t.v1}), f, 1e-15) << i;
    const Vec3 mid = (c.t.v1 + c.t.v2) * 0.5;  // split at an edge's midpoint: additive
    EXPECT_NEAR(analytic(c.x, c.n, {c.t.v0, c.t.v1, mid}) + analytic(c.x, c.n, {c.t.v0, mid, c.t.v2}), f, 1e-13) << i;
  }
}

TEST(AnalyticFormFactor, NeverAboveOneNorBelowZeroAndOneForTheWholeHemisphere) {
  std::mt19937_64 rng(27);
  double largest = 0;
  for (int i = 0; i < 20000; ++i) {
    const Configuration c = random_configuration(rng);
    const double f = analytic(c.x, c.n, c.t);
    ASSERT_GE(f, 0.0) << i;
    ASSERT_LE(f, 1.0) << i;
    largest = std::max(largest, f);
  }
  EXPECT_GT(largest, 0.3);  // the random set does reach large form factors
  // A huge triangle right in front (the receiver's plane cut it to a near-half-plane): close to 1,
  // never above.
  const double big = analytic({0, 0, 0}, {0, 0, 1}, {{-1e9, -1e9, 1e-3}, {1e9, -1e9, 1e-3}, {0, 1e9, 1e-3}});
  EXPECT_LE(big, 1.0);
  EXPECT_GT(big, 0.99);
}

TEST(AnalyticFormFactor, TheSolverKindsAreOneNameListParsedInOnePlace) {
  for (const std::string& name : form_factor_names()) EXPECT_EQ(to_string(parse_form_factor_kind(name)), name);
  EXPECT_EQ(parse_form_factor_kind("analytic"), FormFactorKind::Analytic);
  try {
    parse_form_factor_kind("exact");
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "form factor 'exact' is not one of: point, disc, analytic");
  }
  // The kinds' entry point: the analytic kind takes the polygon, the others only the centres.
  const PairGeometry g = pair_geometry({0.5, 0.5, 1}, {0, 0, -1}, {0.5, 0.5, 0}, {0, 0, 1});
  const Triangle t{{0, 0, 1}, {1, 1, 1}, {1, 0, 1}};
  EXPECT_EQ(form_factor(FormFactorKind::Analytic, g, t, 0.5, {0.5, 0.5, 0}, {0, 0, 1}),
            analytic({0.5, 0.5, 0}, {0, 0, 1}, t));
  EXPECT_EQ(form_factor(FormFactorKind::PointToPoint, g, t, 0.5, {0.5, 0.5, 0}, {0, 0, 1}),
            form_factor(FormFactorKind::PointToPoint, g, 0.5));
}

}  // namespace
}  // namespace rc
