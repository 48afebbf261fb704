#include <gtest/gtest.h>

#include "tests/common/simple_scenes.h"
#include "host_sw/radiosity/float_visibility.h"
#include "host_sw/radiosity/radiosity.h"

namespace rc {
namespace {

SolverResult solve(const Scene& scene, SolverOptions options) {
  FloatVisibility visibility;
  return ProgressiveRadiosity(scene, visibility, options).run();
}

TEST(EnergyBalance, EmittedEqualsAbsorbedPlusEscapingPlusUnshot) {
  const Scene scene = test::cornell_box(2);
  for (FormFactorKind kind : {FormFactorKind::PointToPoint, FormFactorKind::Disc, FormFactorKind::Analytic}) {
    SolverOptions options;
    options.form_factor = kind;
    const SolverResult r = solve(scene, options);
    const EnergyBalance& e = r.energy;
    EXPECT_NEAR(e.absorbed + e.escaping + e.unshot, e.emitted, 1e-12 * e.emitted);
    // The unshot remainder is bounded by the stopping rule: each patch below the threshold.
    EXPECT_LE(e.unshot, (1 - options.convergence) * r.max_initial_power * scene.patches.size());
    EXPECT_GT(e.absorbed, 0.5 * e.emitted);  // a closed-ish box absorbs most of its light
    for (std::size_t i = 0; i < scene.patches.size(); ++i) {
      const Spectrum& emitted = scene.material_of(scene.patches[i]).emission;
      for (std::size_t b = 0; b < kBands; ++b) EXPECT_GE(r.radiosity[i][b], emitted[b]);  // never loses energy
    }
  }
}

TEST(Convergence, StopsAtTheFirstStepBelowTheThreshold) {
  const Scene scene = test::cornell_box(1);
  SolverOptions options;
  options.convergence = 0.99;
  const SolverResult converged = solve(scene, options);
  EXPECT_TRUE(converged.converged);
  EXPECT_LT(converged.max_unshot_power, 0.01 * converged.max_initial_power);
  EXPECT_GE(converged.convergence_reached, 0.99);
  // One step fewer: the largest unshot power was still at or above 1% of the largest emitted power.
  options.fixed_steps = converged.steps - 1;
  const SolverResult before = solve(scene, options);
  EXPECT_EQ(before.steps, converged.steps - 1);
  EXPECT_GE(before.max_unshot_power, 0.01 * before.max_initial_power);
}

// min_steps keeps a converging run going (a recording must cover the steps its replays need);
// past it, the run stops at convergence as usual, and max_steps still caps it.
TEST(Convergence, MinStepsKeepsARunGoingButNotPastConvergence) {
  const Scene scene = test::cornell_box(1);
  SolverOptions options;
  options.convergence = 0.99;
  const int converges_at = solve(scene, options).steps;
  options.min_steps = converges_at + 25;
  EXPECT_EQ(solve(scene, options).steps, converges_at + 25);
  options.min_steps = converges_at - 25;
  EXPECT_EQ(solve(scene, options).steps, converges_at);
  options.min_steps = converges_at + 25;
  options.max_steps = converges_at + 5;
  EXPECT_EQ(solve(scene, options).steps, converges_at + 5);
}

TEST(Determinism, SameInputGivesBitIdenticalOutput) {
  const Scene scene = test::cornell_box(1, 70);
  const SolverResult a = solve(scene, {}), b = solve(scene, {});
  ASSERT_EQ(a.steps, b.steps);
  ASSERT_EQ(a.radiosity.size(), b.radiosity.size());
  for (std::size_t i = 0; i < a.radiosity.size(); ++i) {
    for (std::size_t k = 0; k < kBands; ++k) ASSERT_EQ(a.radiosity[i][k], b.radiosity[i][k]) << "patch " << i;
  }
  EXPECT_EQ(a.energy.absorbed, b.energy.absorbed);
}

TEST(Solver, RejectsBadSettings) {
  const Scene box = test::furnace_box(1, 0.5, 0);
  FloatVisibility v;
  SolverOptions bad;
  bad.convergence = 1.0;
  EXPECT_THROW(ProgressiveRadiosity(box, v, bad), std::invalid_argument);
  const Scene dark = test::furnace_box(0, 0.5, 0);
  EXPECT_THROW(ProgressiveRadiosity(dark, v, {}).run(), std::invalid_argument);
}

}  // namespace
}  // namespace rc

namespace rc {
namespace {

// Paper-faithful mode sends segments to receivers that exchange nothing; their form factor is 0,
// so the solution is the same to the bit, only the work differs.
TEST(PaperFaithful, SegmentsToEveryPatchChangeNoResult) {
  const Scene scene = test::cornell_box(1);
  SolverOptions culled;
  culled.fixed_steps = 150;
  SolverOptions faithful = culled;
  faithful.cull_receivers = false;
  const SolverResult a = solve(scene, culled), b = solve(scene, faithful);
  for (std::size_t i = 0; i < a.radiosity.size(); ++i) {
    for (std::size_t k = 0; k < kBands; ++k) ASSERT_EQ(a.radiosity[i][k], b.radiosity[i][k]) << "patch " << i;
  }
  EXPECT_EQ(b.segments, 150u * (scene.patches.size() - 1));
  EXPECT_LT(a.segments, b.segments);
  EXPECT_EQ(b.receivers_skipped, 0u);
}

}  // namespace
}  // namespace rc
