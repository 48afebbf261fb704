// The guard band on t on the board: the solver's SolverOptions::fixes.t_guard reaches the lanes through
// the T_GUARD register (the driver writes it once, before the first pass; never when it is 0), and the
// fast wrapper and the cycle-level wrapper (clock by clock) give the CPU fixed-point backend's answers
// with the same guard, bit for bit, on a small smooth mesh (a torus in the Cornell Box). Float lanes
// refuse a guard.
#include <gtest/gtest.h>

#include <stdexcept>

#include "board/register_map.h"
#include "tests/common/small_torus_scene.h"
#include "tests/host_sw/platform/system_support.h"

namespace rc::test {
namespace {

void expect_board_matches_cpu(int bits, int g) {
  const Scene scene = small_torus_scene();
  SolverOptions so = steps(12);
  so.fixes.bits = bits;
  so.fixes.t_guard = g;
  SolverOptions unguarded = so;
  unguarded.fixes.t_guard = 0;
  BoardRunOptions o;
  o.lanes = 2;
  o.bits = bits;
  BoardSystem fast("fast", scene, so, setup(o));
  BoardSystem plain("plain", scene, unguarded, setup(o));
  o.model = board::WrapperModel::cycle;
  BoardSystem cycle("cycle", scene, so, setup(o));
  run_all({&fast, &plain, &cycle});
  const SolverResult cpu = cpu_fixed_point(scene, so, bits);
  // The guard changed answers up to 15 bits; at 23 and 31 the faces' |det| is thousands of LSBs, and one or
  // two LSBs of guard leave these 12 steps unchanged (the bits are still compared).
  if (bits <= 15) {
    ASSERT_NE(cpu.blocked_segments, cpu_fixed_point(scene, unguarded, bits).blocked_segments);
  }
  expect_identical(fast.result().radiosity, cpu.radiosity);
  expect_identical(cycle.result().radiosity, cpu.radiosity);
  EXPECT_EQ(fast.result().blocked_segments, cpu.blocked_segments);
  expect_cycle_model_matches_fast(fast, cycle);
  EXPECT_EQ(fast.board.regs.value(board::reg::kTGuard), static_cast<std::uint32_t>(g));
  EXPECT_EQ(plain.board.regs.value(board::reg::kTGuard), 0u);
  // One register access more than the unguarded run: T_GUARD, once.
  EXPECT_EQ(fast.driver().stats().register_accesses, plain.driver().stats().register_accesses + 1);
}

TEST(TGuardSystem, BoardWrappersMatchCpuAt7BitsGuard1) { expect_board_matches_cpu(7, 1); }
TEST(TGuardSystem, BoardWrappersMatchCpuAt11BitsGuard2) { expect_board_matches_cpu(11, 2); }
TEST(TGuardSystem, BoardWrappersMatchCpuAt15BitsGuard4) { expect_board_matches_cpu(15, 4); }
TEST(TGuardSystem, BoardWrappersMatchCpuAt23BitsGuard2) { expect_board_matches_cpu(23, 2); }
TEST(TGuardSystem, BoardWrappersMatchCpuAt31BitsGuard1) { expect_board_matches_cpu(31, 1); }

TEST(TGuardSystem, FloatLanesRefuseAGuard) {
  const Scene scene = small_torus_scene();
  SolverOptions so = steps(2);
  so.fixes.bits = 15;
  so.fixes.t_guard = 1;
  BoardRunOptions o;
  o.float_format = pipeline::parse_float_format("float:8,23");
  EXPECT_THROW(BoardSystem("float", scene, so, setup(o)), std::invalid_argument);
}

}  // namespace
}  // namespace rc::test
