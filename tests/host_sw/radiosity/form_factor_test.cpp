// Form factors against the analytic cases of shared/data/cornell-box.md.
#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>

#include "host_sw/radiosity/form_factor.h"
#include "scenes/subdivide.h"

namespace rc {
namespace {

// Single centre-to-centre evaluations: the data sheet's "point formula" and "disc formula" columns.
TEST(FormFactor, CentreToCentreMatchesTheDataSheetColumns) {
  // Two unit squares, parallel and facing, distance 1.
  const PairGeometry parallel = pair_geometry({0.5, 0.5, 0}, {0, 0, 1}, {0.5, 0.5, 1}, {0, 0, -1});
  EXPECT_NEAR(form_factor(FormFactorKind::PointToPoint, parallel, 1.0), 0.3183, 5e-5);
  EXPECT_NEAR(form_factor(FormFactorKind::Disc, parallel, 1.0), 0.2415, 5e-5);
  // Perpendicular, sharing an edge (z = 0 plane and x = 0 plane).
  const PairGeometry perpendicular = pair_geometry({0.5, 0.5, 0}, {0, 0, 1}, {0, 0.5, 0.5}, {1, 0, 0});
  EXPECT_NEAR(form_factor(FormFactorKind::PointToPoint, perpendicular, 1.0), 0.3183, 5e-5);
  EXPECT_NEAR(form_factor(FormFactorKind::Disc, perpendicular, 1.0), 0.1945, 5e-5);
}

TEST(FormFactor, BehindOrFacingAwayExchangesNothing) {
  EXPECT_FALSE(pair_geometry({0, 0, 0}, {0, 0, 1}, {0, 0, -1}, {0, 0, 1}).exchanges());  // behind
  EXPECT_FALSE(pair_geometry({0, 0, 0}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}).exchanges());   // facing away
  EXPECT_FALSE(pair_geometry({0, 0, 0}, {0, 0, 1}, {1, 0, 0}, {0, 0, 1}).exchanges());   // coplanar
  EXPECT_EQ(form_factor(FormFactorKind::Disc, pair_geometry({0, 0, 0}, {0, 0, 1}, {0, 0, -1}, {0, 0, 1}), 1.0), 0.0);
}

// Area-weighted patch sum F(A->B) = sum_i A_i/A_A sum_j F(i <- j) over `levels` of subdivision.
double square_to_square(const Triangle (&a)[2], const Triangle (&b)[2], int levels, FormFactorKind kind) {
  std::vector<Face> fa{{a[0]}, {a[1]}}, fb{{b[0]}, {b[1]}};
  const auto pa = make_patches(fa, levels), pb = make_patches(fb, levels);
  double sum = 0, area = 0;
  for (const Patch& i : pa) {
    area += i.area;
    for (const Patch& j : pb) sum += i.area * form_factor(kind, pair_geometry(j.centre, j.normal, i.centre, i.normal), j.area);
  }
  return sum / area;
}

// Subdivided, both formulas converge to the exact value. The point rule's error shrinks with the
// patch size (h^2 away from edges); at the shared edge of the perpendicular case it converges
// only as h, so the tolerance there is looser. Tolerances are ~1.5x the error measured at level 4.
TEST(FormFactor, SubdividedParallelSquaresConvergeToExact) {
  const Triangle a[2] = {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}, {{0, 0, 0}, {1, 1, 0}, {0, 1, 0}}};
  const Triangle b[2] = {{{0, 0, 1}, {1, 1, 1}, {1, 0, 1}}, {{0, 0, 1}, {0, 1, 1}, {1, 1, 1}}};
  const double coarse = square_to_square(a, b, 1, FormFactorKind::PointToPoint);
  const double fine = square_to_square(a, b, 4, FormFactorKind::PointToPoint);
  std::printf("parallel: point %.5f (level 1: %.5f) disc %.5f\n", fine, coarse, square_to_square(a, b, 4, FormFactorKind::Disc));
  EXPECT_LT(std::abs(fine - 0.1998), std::abs(coarse - 0.1998));
  EXPECT_NEAR(fine, 0.1998, 5e-4);
  EXPECT_NEAR(square_to_square(a, b, 4, FormFactorKind::Disc), 0.1998, 5e-4);
}

TEST(FormFactor, SubdividedPerpendicularSquaresConvergeToExact) {
  const Triangle a[2] = {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}, {{0, 0, 0}, {1, 1, 0}, {0, 1, 0}}};
  const Triangle b[2] = {{{0, 0, 0}, {0, 1, 0}, {0, 1, 1}}, {{0, 0, 0}, {0, 1, 1}, {0, 0, 1}}};
  const double fine_point = square_to_square(a, b, 4, FormFactorKind::PointToPoint);
  const double fine_disc = square_to_square(a, b, 4, FormFactorKind::Disc);
  std::printf("perpendicular: point %.5f disc %.5f\n", fine_point, fine_disc);
  EXPECT_NEAR(fine_point, 0.2000, 1.2e-2);
  EXPECT_NEAR(fine_disc, 0.2000, 1.5e-3);
}

// A receiver point on the axis of a disc of radius R at height h: F = R^2 / (R^2 + h^2).
TEST(FormFactor, DiscOnAxisConvergesToExact) {
  const double R = 1.0, h = 0.5, exact = R * R / (R * R + h * h);
  // A polar grid of small cells (rings x sectors, two triangles each) so that every patch is small
  // and compact; a fan of thin slivers would hide the quadrature's convergence.
  const int rings = 64, sectors = 256;
  std::vector<Face> disc;
  auto at = [&](int ring, int sector) {
    const double r = R * ring / rings, a = 2 * glm::pi<double>() * sector / sectors;
    return Vec3(r * std::cos(a), r * std::sin(a), 0);
  };
  for (int i = 0; i < rings; ++i) {
    for (int k = 0; k < sectors; ++k) {
      if (i > 0) disc.push_back({{at(i, k), at(i + 1, k), at(i, k + 1)}});
      disc.push_back({{at(i, k + 1), at(i + 1, k), at(i + 1, k + 1)}});
    }
  }
  for (FormFactorKind kind : {FormFactorKind::PointToPoint, FormFactorKind::Disc}) {
    double f = 0;
    for (const Patch& p : make_patches(disc, 0)) {
      f += form_factor(kind, pair_geometry(p.centre, p.normal, {0, 0, h}, {0, 0, -1}), p.area);
    }
    std::printf("disc on axis (%s): %.6f exact %.6f\n", to_string(kind).c_str(), f, exact);
    // The 256-gon misses 0.01% of the disc's area (about 1e-4 of F); the rest is quadrature.
    EXPECT_NEAR(f, exact, 2e-4);
  }
}

}  // namespace
}  // namespace rc
