// The solver's guards (docs/radiosity.md, Guards): a solve that creates energy or produces values
// that are not finite stops with SolveDiverged and advice, instead of running to the step cap and
// writing inf; rendering refuses a degenerate camera and radiosity that is not finite.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "host_sw/radiosity/float_visibility.h"
#include "host_sw/radiosity/radiosity.h"
#include "host_sw/radiosity/render.h"
#include "scenes/normalise.h"
#include "scenes/prepare.h"
#include "scenes/subdivide.h"
#include "tests/common/simple_scenes.h"
#include "tests/host_sw/radiosity/guard_support.h"

namespace rc {
namespace {

using test::contains;
using test::divergence_of;
using test::solve;

// A quad folded like a closing book (its two triangles face each other, 23 degrees apart: what a
// scene file refuses now, built here by hand as a mesh could give it) lit through its opening by a
// wall lamp. The point form factor across the fold is about 4 at every patch size.
Scene folded_quad_scene(int patch_levels) {
  Scene s;
  s.name = "fold";
  s.surface_names = {"fold", "lamp"};
  s.materials.push_back({"white", Spectrum::uniform(0.9), Spectrum{}});
  s.materials.push_back({"lamp", Spectrum::uniform(0.5), Spectrum::uniform(10)});
  const Vec3 v0(0, 0, 0), v1(0, 0, 1), v2(1, 0, 1), v3(0, 0.3, 1);
  s.faces.push_back({{v0, v1, v2}, 0, 0});
  s.faces.push_back({{v0, v2, v3}, 0, 0});
  const Vec3 l0(-0.5, 0, 0), l1(-0.5, 1, 0), l2(-0.5, 1, 2), l3(-0.5, 0, 2);
  s.faces.push_back({{l0, l1, l2}, 1, 1});
  s.faces.push_back({{l0, l2, l3}, 1, 1});
  s.camera = {{-2, 0.5, 0.5}, {0.5, 0.1, 0.5}, {0, 1, 0}, 60};
  normalise(s);
  s.patches = make_patches(s.faces, patch_levels);
  return s;
}


// Before the guard this solve ran the 10,000,000 steps of the cap and wrote inf.
TEST(SolveGuard, AFoldedQuadStopsWithTheStepThePairAndAdvice) {
  for (int levels : {1, 3}) {
    const std::string m = divergence_of(folded_quad_scene(levels), FormFactorKind::PointToPoint);
    SCOPED_TRACE(m);
    // The unshot total passes the emitted power before anything absorbs more than was emitted.
    EXPECT_TRUE(contains(m, levels == 1 ? "the solve diverged at step 18: " : "the solve diverged at step 188: "));
    EXPECT_TRUE(contains(m, "exceeds the emitted power 15 (the form factors create energy"));
    EXPECT_TRUE(contains(m, "surface 'fold'"));
    EXPECT_TRUE(contains(m, "(above 1: the patches are close against their size)"));
    EXPECT_TRUE(contains(m, "share an edge and fold onto each other (their normals are 157 degrees apart): "
                            "the two triangles of one quad, which is not planar; fix its vertices"));
    EXPECT_TRUE(contains(m, "smaller patches do not help"));
    EXPECT_TRUE(contains(m, "its largest form factor (point), to patch "));
    EXPECT_TRUE(contains(m, "Try --form-factor analytic (never creates energy)"));
    EXPECT_TRUE(contains(m, "docs/radiosity.md, Guards"));
  }
}

TEST(SolveGuard, TheDiscFormFactorSolvesTheSameFoldAndStaysWithinTheEmittedPower) {
  const SolverResult r = solve(folded_quad_scene(3), FormFactorKind::Disc);
  EXPECT_TRUE(r.converged);
  EXPECT_LE(r.energy.unshot, r.energy.emitted);
  for (const Spectrum& b : r.radiosity) EXPECT_TRUE(std::isfinite(b.sum()));
}

// The guard never fires on the shipped scenes, although the point rule overshoots there: the
// default box's floor patches next to the blocks see form factors up to 2.7 and 15 of its steps
// give back more than they shoot. The total stays below what the light emitted.
TEST(SolveGuard, ConvergingSolvesOfTheCornellBoxPass) {
  for (int levels : {0, 1, 2}) {
    for (FormFactorKind kind : {FormFactorKind::PointToPoint, FormFactorKind::Disc}) {
      EXPECT_EQ(divergence_of(test::cornell_box(levels), kind), "") << levels;
    }
  }
  EXPECT_EQ(divergence_of(test::cornell_box(1, 70), FormFactorKind::PointToPoint), "");
  for (int levels : {0, 1, 2, 3}) EXPECT_EQ(divergence_of(test::cornell_box(levels), FormFactorKind::Analytic), "") << levels;
}

TEST(SolveGuard, TheAnalyticFormFactorSolvesTheFoldWithinTheEmittedPower) {
  const SolverResult r = solve(folded_quad_scene(3), FormFactorKind::Analytic);
  EXPECT_TRUE(r.converged);
  EXPECT_LE(r.energy.absorbed, r.energy.emitted);
  EXPECT_GE(r.energy.escaping, -1e-12 * r.energy.emitted);
}

TEST(SolveGuard, EmittedPowerThatIsNotFiniteIsRefusedBeforeSolving) {
  Scene s = test::furnace_box(5e307, 0.5, 0);
  FloatVisibility visibility;
  try {
    ProgressiveRadiosity(s, visibility, SolverOptions{}).run();
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_TRUE(contains(e.what(), "the emitted power (emission x area, summed over patches and bands) is not finite"));
  }
}

// The same scene at 1e200 and at 2^-1000 solves as at unit size: normalisation makes the faces
// bit-identical (powers of two) or equal within rounding, and radiosity is scale-free.
TEST(SolveGuard, ScenesAtExtremeScalesSolveAsAtUnitSize) {
  auto scaled_room = [](double k) {
    Scene s = test::furnace_box(0, 0.6, 0);  // a closed cube; its top gets a lamp material
    s.materials.push_back({"lamp", Spectrum::uniform(0.5), Spectrum::uniform(4)});
    s.faces[2].material = s.faces[3].material = 1;
    for (Face& f : s.faces)
      for (Vec3* v : {&f.tri.v0, &f.tri.v1, &f.tri.v2}) *v = *v * k;
    s.camera = {Vec3(0.5, 0.5, -2) * k, Vec3(0.5, 0.5, 0) * k, {0, 1, 0}, 50};
    normalise(s);
    s.patches = make_patches(s.faces, 2);
    return solve(s, FormFactorKind::Disc);
  };
  const SolverResult unit = scaled_room(1);
  const SolverResult exact = scaled_room(std::ldexp(1.0, -1000));
  const SolverResult huge = scaled_room(1e200);
  ASSERT_EQ(exact.radiosity.size(), unit.radiosity.size());
  for (std::size_t i = 0; i < unit.radiosity.size(); ++i) {
    EXPECT_EQ(exact.radiosity[i].band, unit.radiosity[i].band);
    EXPECT_NEAR(huge.radiosity[i][0], unit.radiosity[i][0], 1e-9 * unit.radiosity[i][0]);
  }
}

TEST(RenderGuard, RefusesADegenerateCameraAndRadiosityThatIsNotFinite) {
  Scene s = test::cornell_box(0);
  const std::vector<Spectrum> radiosity(s.patches.size(), Spectrum::uniform(1));
  RenderOptions small;
  small.width = small.height = 16;
  EXPECT_NO_THROW(render_radiosity(s, radiosity, small));
  s.camera.up = s.camera.look_at - s.camera.position;
  try {
    render_radiosity(s, radiosity, small);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_TRUE(contains(e.what(), "is parallel to the view direction")) << e.what();
  }
  s = test::cornell_box(0);
  std::vector<Spectrum> bad = radiosity;
  bad[5][1] = NAN;
  try {
    render_radiosity(s, bad, small);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "the radiosity of patch 5 is not finite");
  }
}

}  // namespace
}  // namespace rc
