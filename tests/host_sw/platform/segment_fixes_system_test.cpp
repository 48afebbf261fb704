// The segment fixes (host_sw/radiosity/segment_fixes.h) on the board: the solver moves the batch and
// re-checks the answers on the host, so the board's lanes (fast wrapper, and the cycle-level wrapper
// clock by clock) give the CPU fixed-point backend's answers bit for bit, at 7, 15 and 31 bits (all three
// fixes; coordinates 4 bits narrower than the lanes above 7 bits), on a
// small smooth mesh (a torus in the Cornell Box).
#include <gtest/gtest.h>

#include "tests/common/small_torus_scene.h"
#include "tests/host_sw/platform/system_support.h"

namespace rc::test {
namespace {

void expect_board_matches_cpu(int bits) {
  const Scene scene = small_torus_scene();
  SolverOptions so = steps(12);
  so.fixes = {bits, 2, 1, bits > 7 ? bits - 4 : 0};
  BoardRunOptions o;
  o.lanes = 2;
  o.bits = bits;
  BoardSystem fast("fast", scene, so, setup(o));
  o.model = board::WrapperModel::cycle;
  BoardSystem cycle("cycle", scene, so, setup(o));
  run_all({&fast, &cycle});
  const SolverResult cpu = cpu_fixed_point(scene, so, bits);
  ASSERT_GT(cpu.fix_cleared, 0u);  // the neighbour rule changed answers
  expect_identical(fast.result().radiosity, cpu.radiosity);
  expect_identical(cycle.result().radiosity, cpu.radiosity);
  EXPECT_EQ(fast.result().blocked_segments, cpu.blocked_segments);
  EXPECT_EQ(fast.result().fix_tests, cpu.fix_tests);
  expect_cycle_model_matches_fast(fast, cycle);
}

TEST(SegmentFixesSystem, BoardWrappersMatchCpuAt7Bits) { expect_board_matches_cpu(7); }
TEST(SegmentFixesSystem, BoardWrappersMatchCpuAt15Bits) { expect_board_matches_cpu(15); }
TEST(SegmentFixesSystem, BoardWrappersMatchCpuAt31Bits) { expect_board_matches_cpu(31); }

}  // namespace
}  // namespace rc::test
