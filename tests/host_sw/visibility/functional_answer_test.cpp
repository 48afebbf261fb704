// The functional answer behind recordings and board oracles skips segments the solver does not
// need and reuses a repeated shooter's answer (visibility_factory.h). Neither may change a bit.
#include <gtest/gtest.h>

#include "host_sw/visibility/fixed_visibility.h"
#include "host_sw/visibility/needed_only_visibility.h"
#include "host_sw/radiosity/radiosity.h"
#include "host_sw/visibility/shooter_memo_visibility.h"
#include "host_sw/visibility/visibility_factory.h"
#include "tests/common/simple_scenes.h"

namespace rc {
namespace {

void expect_same_solution(const SolverResult& a, const SolverResult& b) {
  ASSERT_EQ(a.radiosity.size(), b.radiosity.size());
  for (std::size_t i = 0; i < a.radiosity.size(); ++i) {
    for (std::size_t k = 0; k < kBands; ++k) ASSERT_EQ(a.radiosity[i][k], b.radiosity[i][k]) << "patch " << i;
  }
  EXPECT_EQ(a.steps, b.steps);
  EXPECT_EQ(a.segments, b.segments);
  EXPECT_EQ(a.blocked_segments, b.blocked_segments);
  EXPECT_EQ(a.energy.absorbed, b.energy.absorbed);
  EXPECT_EQ(a.energy.escaping, b.energy.escaping);
}

// Paper-faithful (a segment to every patch) and culled, converged: the brute-force pipeline model
// answering everything, against the same model behind both wrappers, and the culled kernel too.
TEST(FunctionalAnswer, SkippingAndReuseChangeNoResult) {
  const Scene scene = test::cornell_box(1);
  for (const bool cull : {false, true}) {
    SCOPED_TRACE(cull ? "culled" : "paper-faithful");
    SolverOptions options;
    options.cull_receivers = cull;
    options.convergence = 0.999;
    FixedPointVisibility brute(15);
    const SolverResult expected = ProgressiveRadiosity(scene, brute, options).run();

    auto needed_only = std::make_unique<NeededOnlyVisibility>(std::make_unique<FixedPointVisibility>(15));
    const NeededOnlyVisibility& skipping = *needed_only;
    ShooterMemoVisibility memo(std::move(needed_only));
    expect_same_solution(ProgressiveRadiosity(scene, memo, options).run(), expected);
    EXPECT_GT(memo.batches_reused(), 0u) << "a converged run shoots some patches again";
    EXPECT_EQ(memo.batches_reused() + memo.batches_answered(), static_cast<std::uint64_t>(expected.steps));
    if (cull) {
      EXPECT_EQ(skipping.segments_skipped(), 0u);
    } else {
      EXPECT_GT(skipping.segments_skipped(), 0u);
    }
    EXPECT_LT(memo.tests_performed(), brute.tests_performed());

    auto fast = make_functional_answer("fast", 15, 2);
    expect_same_solution(ProgressiveRadiosity(scene, *fast, options).run(), expected);
  }
}

// Unneeded segments are not asked about and come back clear; needed ones keep their answers.
TEST(FunctionalAnswer, UnneededSegmentsAreNotAskedAboutAndReportedClear) {
  const std::vector<Triangle> faces = {{{0.1, 0.1, 0.1}, {0.9, 0.1, 0.1}, {0.1, 0.9, 0.1}},
                                       {{0.1, 0.1, 0.9}, {0.1, 0.9, 0.9}, {0.9, 0.1, 0.9}},
                                       {{0.0, 0.0, 0.5}, {0.99, 0.0, 0.5}, {0.0, 0.99, 0.5}}};
  SegmentBatch batch;
  batch.start = faces[0].centroid();
  batch.source_face = 0;
  batch.ends = {faces[1].centroid(), faces[1].centroid(), faces[1].centroid()};
  batch.end_faces = {1, 1, 1};
  batch.needed = {1, 0, 1};
  NeededOnlyVisibility v(std::make_unique<FixedPointVisibility>(15));
  v.load_faces(faces);
  v.submit(batch);
  std::vector<std::uint8_t> blocked;
  v.collect(blocked);
  EXPECT_EQ(blocked, (std::vector<std::uint8_t>{1, 0, 1}));  // face 2 lies between, but segment 1 is not needed
  EXPECT_EQ(v.segments_skipped(), 1u);
  EXPECT_EQ(v.tests_performed(), 2u);  // two segments against face 2 (faces 0 and 1 are their own)

  batch.needed = {1, 0};
  EXPECT_THROW(v.submit(batch), std::invalid_argument);
}

// A shooter id promises the same batch; a different one is an error, not a wrong answer. Loading
// faces starts a new run, in which ids promise nothing about the old one.
TEST(FunctionalAnswer, ABrokenShooterPromiseIsAnErrorAndLoadingFacesForgets) {
  const std::vector<Triangle> faces = {{{0.1, 0.1, 0.1}, {0.9, 0.1, 0.1}, {0.1, 0.9, 0.1}},
                                       {{0.1, 0.1, 0.9}, {0.1, 0.9, 0.9}, {0.9, 0.1, 0.9}}};
  SegmentBatch batch;
  batch.start = faces[0].centroid();
  batch.source_face = 0;
  batch.ends = {faces[1].centroid()};
  batch.end_faces = {1};
  batch.shooter = 7;
  ShooterMemoVisibility memo(std::make_unique<FixedPointVisibility>(15));
  memo.load_faces(faces);
  std::vector<std::uint8_t> blocked;
  memo.submit(batch);
  memo.collect(blocked);
  memo.submit(batch);
  memo.collect(blocked);
  EXPECT_EQ(memo.batches_reused(), 1u);
  SegmentBatch moved = batch;
  moved.start.x += 0.01;
  EXPECT_THROW(memo.submit(moved), std::logic_error);
  memo.load_faces(faces);
  memo.submit(moved);
  memo.collect(blocked);
  EXPECT_EQ(memo.batches_reused(), 1u);
  EXPECT_EQ(memo.batches_answered(), 2u);
}

}  // namespace
}  // namespace rc
