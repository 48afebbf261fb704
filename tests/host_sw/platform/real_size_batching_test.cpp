// Paper sec 4.4 at the sizes it names, with the profile's real 4 MB banks (no shrunk banks): more
// faces than one face bank holds (116,508 with the own-face table in a spare bank) and more rays
// than one batch holds (2^20 with one lane). A few steps each, so that CI can afford them; the
// culled fixed-point kernel (proven bit-identical to the lanes) answers for the lanes, and the CPU
// reference is the same kernel run on its own.
#include <gtest/gtest.h>

#include "host_sw/visibility/fast_visibility.h"
#include "scenes/prepare.h"
#include "tests/host_sw/platform/system_support.h"

namespace rc::test {
namespace {

// What a one-lane board run with the real 4 MiB banks did, checked against the CPU kernel.
struct RealSizeRun {
  board::BankLayout layout;
  BoardDriverStats stats;
  SolverResult cpu;
};

RealSizeRun run_and_compare(const Scene& scene, const SolverOptions& so) {
  FastFixedVisibility oracle(15);
  BoardRunOptions o;
  o.lanes = 1;
  o.oracle = &oracle;
  BoardSystem board("board", scene, so, setup(o));
  run_all({&board});
  FastFixedVisibility cpu_kernel(15);
  RealSizeRun r{board.board.layout(), board.driver().stats(), ProgressiveRadiosity(scene, cpu_kernel, so).run()};
  EXPECT_GT(r.cpu.blocked_segments, 0u);
  EXPECT_EQ(board.result().blocked_segments, r.cpu.blocked_segments);
  expect_identical(board.result().radiosity, r.cpu.radiosity);
  return r;
}

// 38 x 4^6 = 155,648 faces: two face sets per step.
TEST(RealSizeBatching, MoreFacesThanOneBankHolds) {
  SceneOptions options;
  options.face_levels = 6;
  options.patch_levels = 0;
  const Scene scene = prepare_scene(options).scene;
  ASSERT_EQ(scene.faces.size(), 155648u);
  const RealSizeRun r = run_and_compare(scene, steps(2));
  EXPECT_EQ(r.layout.max_faces_per_set, 116508u);  // floor(4 MiB / 4 / 9)
  EXPECT_EQ(r.stats.face_sets, 2u);
  EXPECT_EQ(r.stats.passes, 2u * 2u);  // every step: one batch against both sets
}

// 38 x 4^8 = 2,490,368 patches: a step's segments in three batches of at most 2^20 (one lane).
TEST(RealSizeBatching, MorePatchesThanOneBatchHolds) {
  SceneOptions options;
  options.patch_levels = 8;
  const Scene scene = prepare_scene(options).scene;
  ASSERT_EQ(scene.patches.size(), 2490368u);
  SolverOptions so = steps(1);
  so.cull_receivers = false;  // paper-faithful: a segment to every other patch
  const RealSizeRun r = run_and_compare(scene, so);
  EXPECT_EQ(r.layout.max_rays_per_batch, std::uint64_t{1} << 20);
  ASSERT_GT(r.cpu.segments, std::uint64_t{1} << 21);  // more than two batches' worth
  EXPECT_EQ(r.stats.max_batches_per_step, (r.cpu.segments + (1u << 20) - 1) >> 20);
}

}  // namespace
}  // namespace rc::test
