#include <gtest/gtest.h>

#include <numeric>

#include "host_sw/studies/adaptive_study.h"

namespace rc {
namespace {

TEST(AdaptiveStudy, RoundCountsGrowGeometricallyBySplitsToTheTarget) {
  EXPECT_EQ(round_counts(38, 608, 5), (std::vector<std::size_t>{38, 77, 152, 305, 608}));
  EXPECT_EQ(round_counts(38, 152, 2), (std::vector<std::size_t>{38, 152}));
  for (std::size_t n : round_counts(38, 2432, 7)) EXPECT_EQ((n - 38) % 3, 0u) << n;
  EXPECT_THROW(round_counts(38, 152, 1), std::invalid_argument);
  EXPECT_THROW(round_counts(38, 150, 3), std::invalid_argument);  // not reachable by splits
  EXPECT_THROW(round_counts(152, 38, 3), std::invalid_argument);
}

TEST(AdaptiveStudy, SamplingACoarseSolutionAtFinerPatchesGivesEachItsParentsValue) {
  SceneOptions o;
  o.patch_levels = 1;
  const Scene coarse = prepare_scene(o).scene;
  o.patch_levels = 2;
  const Scene fine = prepare_scene(o).scene;
  std::vector<Spectrum> b(coarse.patches.size());
  for (std::size_t i = 0; i < b.size(); ++i) b[i] = Spectrum::uniform(static_cast<double>(i));
  const std::vector<Spectrum> at = sample_at_finer(coarse, b, fine);
  ASSERT_EQ(at.size(), fine.patches.size());
  for (std::size_t i = 0; i < at.size(); ++i) EXPECT_EQ(at[i][0], static_cast<double>(i / 4)) << i;  // uniform children in order
  EXPECT_THROW(sample_at_finer(coarse, std::vector<Spectrum>(3), fine), std::invalid_argument);
  Scene fewer_faces = fine;
  fewer_faces.faces.pop_back();
  EXPECT_THROW(sample_at_finer(coarse, b, fewer_faces), std::invalid_argument);
}

// The whole study, small: the embedded box's faces, uniform level 1 against adaptive from level 0
// in two solves, reference at level 2.
TEST(AdaptiveStudy, AdaptiveRunsMatchTheUniformCountAndPayForEverySolve) {
  AdaptiveSpec s;
  s.levels = {1};
  s.start_levels = 0;
  s.rounds = 3;
  s.reference_levels = 2;
  s.image_size = 64;
  s.board.concurrent = true;
  s.board.host = "athlon-mp-2600-calibrated";
  const AdaptiveResult r = run_adaptive_study(s, [](const std::string&) {});
  ASSERT_EQ(r.runs.size(), 2u);
  const PatchingRun& uniform = r.runs[0];
  const PatchingRun& adaptive = r.runs[1];
  EXPECT_EQ(uniform.kind, "uniform");
  EXPECT_EQ(adaptive.kind, "adaptive");
  ASSERT_EQ(adaptive.solves.size(), 3u);
  EXPECT_EQ(adaptive.final_solve().scene.patches.size(), uniform.final_solve().scene.patches.size());
  EXPECT_EQ(adaptive.solves[0].scene.patches.size(), r.reference_scene.faces.size());  // level 0: one patch a face
  double sum = 0;
  for (const PatchingSolve& p : adaptive.solves) {
    EXPECT_GT(p.simulated_seconds, 0);
    sum += p.simulated_seconds;
  }
  EXPECT_EQ(adaptive.simulated_seconds(), sum);
  EXPECT_EQ(uniform.simulated_seconds(), uniform.final_solve().simulated_seconds);
  // The errors are the sampled final solutions against the reference, as documented.
  const PatchingSolve& f = adaptive.final_solve();
  EXPECT_EQ(adaptive.error.rmse,
            compare_solutions(sample_at_finer(f.scene, f.run.result.radiosity, r.reference_scene), r.reference.radiosity).rmse);
  EXPECT_GT(uniform.error.relative_rmse(), 0);
  EXPECT_GT(adaptive.image_difference, 0);
}

TEST(AdaptiveStudy, SpecsThatCannotRunAreRefused) {
  AdaptiveSpec s;
  s.levels = {3};
  s.reference_levels = 2;
  EXPECT_THROW(run_adaptive_study(s, [](const std::string&) {}), std::invalid_argument);
  s.levels = {1};
  s.start_levels = 1;
  EXPECT_THROW(run_adaptive_study(s, [](const std::string&) {}), std::invalid_argument);
  s.start_levels = 0;
  s.rounds = 1;
  EXPECT_THROW(run_adaptive_study(s, [](const std::string&) {}), std::invalid_argument);
}

}  // namespace
}  // namespace rc
