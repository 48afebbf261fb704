// On the paper's Cornell Box scenes, the fast backend gives the brute force's flags on every
// segment of every step, and whole radiosity solutions identical to the last bit.
#include <gtest/gtest.h>

#include <cstring>

#include "tests/host_sw/visibility/fast_test_support.h"
#include "host_sw/radiosity/radiosity.h"
#include "tests/common/simple_scenes.h"

namespace rc {
namespace {

// Runs the fast backend and the brute force side by side on the solver's own batches, counting
// differing flags; the solver follows the fast backend's answers.
class SideBySide : public VisibilityBackend {
 public:
  SideBySide(int bits, int threads) : fast_(bits, threads), brute_(bits) {}
  std::string name() const override { return "side-by-side"; }
  void load_triangles(const std::vector<Triangle>& faces) override {
    fast_.load_faces(faces, sheets());
    brute_.load_faces(faces, sheets());
  }
  void submit(const SegmentBatch& batch) override {
    brute_.submit(batch);
    fast_.submit(batch);
  }
  void collect(std::vector<std::uint8_t>& blocked) override {
    std::vector<std::uint8_t> expected;
    brute_.collect(expected);
    fast_.collect(blocked);
    ASSERT_EQ(blocked.size(), expected.size());
    for (std::size_t i = 0; i < blocked.size(); ++i) {
      differing += blocked[i] != expected[i];
      blocked_segments += expected[i];
    }
  }
  std::uint64_t tests_performed() const override { return fast_.tests_performed(); }

  std::size_t differing = 0, blocked_segments = 0;
  FastFixedVisibility fast_;
  FixedPointVisibility brute_;
};

void expect_every_step_matches(const Scene& scene, int steps, int bits, int threads) {
  SideBySide both(bits, threads);
  SolverOptions options;
  options.fixed_steps = steps;
  const SolverResult r = ProgressiveRadiosity(scene, both, options).run();
  EXPECT_EQ(both.differing, 0u) << scene.faces.size() << " faces, " << bits << " bits";
  // At 7 bits small faces truncate det and t to almost nothing and block nothing at all.
  if (bits > 7) {
    EXPECT_GT(both.blocked_segments, 0u) << scene.faces.size() << " faces, " << bits << " bits";
  }
  EXPECT_EQ(both.fast_.brute_force_tests(), both.brute_.tests_performed());
  EXPECT_GT(r.segments, 0u);
}

TEST(FastCornell, EveryStepMatchesBruteForceOnThePaperSceneSizes) {
  for (int bits : {7, 11, 15, 23, 31}) {
    expect_every_step_matches(test::cornell_box(1, 70, 0), 385, bits, 2);  // 70 faces, 280 patches
    expect_every_step_matches(test::cornell_box(1, 70, 1), 300, bits, 2);  // 280 faces, 1120 patches
  }
}

TEST(FastCornell, LargestSceneFirstStepsMatchBruteForce) {
  const Scene scene = test::cornell_box(1, 70, 2);  // 1120 faces, 4480 patches
  ASSERT_EQ(scene.faces.size(), 1120u);
  ASSERT_EQ(scene.patches.size(), 4480u);
  for (int bits : {7, 15, 31}) expect_every_step_matches(scene, 25, bits, 3);
}

bool same_bits(const std::vector<Spectrum>& a, const std::vector<Spectrum>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Spectrum)) == 0;
}

// Two independent solutions, each following its own backend's answers: identical to the bit.
TEST(FastCornell, RadiositySolutionIsBitIdenticalToBruteForce) {
  const Scene scene = test::cornell_box(1, 70, 1);  // 280 faces, 1120 patches
  for (int bits : {7, 11, 15, 23, 31}) {
    SolverOptions options;
    options.fixed_steps = 400;
    FixedPointVisibility brute(bits);
    FastFixedVisibility fast(bits, 2);
    const SolverResult expected = ProgressiveRadiosity(scene, brute, options).run();
    const SolverResult actual = ProgressiveRadiosity(scene, fast, options).run();
    EXPECT_TRUE(same_bits(actual.radiosity, expected.radiosity)) << bits << " bits";
    EXPECT_EQ(actual.blocked_segments, expected.blocked_segments);
    EXPECT_EQ(actual.segments, expected.segments);
    EXPECT_EQ(std::memcmp(&actual.energy, &expected.energy, sizeof expected.energy), 0);
    EXPECT_GT(expected.blocked_segments, 0u);
    EXPECT_EQ(fast.brute_force_tests(), brute.tests_performed());
    // At 7 bits the truncation error is a large part of the scene, and so is every hit region.
    // Faces whose regions hold more than 1/128 of a step's segments run the streaming kernel over
    // all of them (cheaper per test); the regions themselves must let through under 1/50, and
    // few faces may go dense.
    EXPECT_LT(fast.tests_performed() - fast.dense_tests(), brute.tests_performed() / (bits == 7 ? 1 : 50)) << bits << " bits";
    EXPECT_LT(fast.dense_tests(), brute.tests_performed() / (bits == 7 ? 2 : 4)) << bits << " bits";
  }
}

// Run to convergence on the smallest paper scene, as the paper does.
TEST(FastCornell, ConvergedSolutionIsBitIdenticalToBruteForce) {
  const Scene scene = test::cornell_box(1, 70, 0);  // 70 faces, 280 patches
  FixedPointVisibility brute(15);
  FastFixedVisibility fast(15, 0);
  const SolverResult expected = ProgressiveRadiosity(scene, brute, SolverOptions{}).run();
  const SolverResult actual = ProgressiveRadiosity(scene, fast, SolverOptions{}).run();
  EXPECT_TRUE(expected.converged);
  EXPECT_EQ(actual.steps, expected.steps);
  EXPECT_TRUE(same_bits(actual.radiosity, expected.radiosity));
}

}  // namespace
}  // namespace rc
