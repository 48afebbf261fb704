// The RTL lanes (rtl/lanes: the Verilated rtl/mt_pipeline.v, one model per lane) inside the SystemC
// board, clocked by the cycle-level wrapper: a small scene's run gives every patch's radiosity bit for
// bit, the same simulated end time (exact sc_time), FPGA busy time, wrapper cycles and bank traffic as
// the C++ lanes (both the cycle-level and the fast wrapper). Where they do not apply they are refused.
// Without Verilator (or at a width not built) the runs print "SKIP: <reason>" and are skipped.
#include <iostream>
#include <stdexcept>

#include <gtest/gtest.h>

#include "rtl/lanes/rtl_lanes.h"
#include "rtl/sim/rtl_pipeline.h"
#include "tests/host_sw/platform/system_support.h"

namespace rc::test {
namespace {

#define REQUIRE_RTL(bits)                                      \
  do {                                                         \
    const std::string why = rtl::rtl_unavailable_reason(bits); \
    if (!why.empty()) {                                        \
      std::cout << "SKIP: RTL lanes: " << why << "\n";         \
      GTEST_SKIP() << why;                                     \
    }                                                          \
  } while (0)

void expect_rtl_lanes_match_cpp(int bits, unsigned lanes, int step_count) {
  const Scene scene = small_cornell_box();
  const SolverOptions so = steps(step_count);
  BoardRunOptions o;
  o.lanes = lanes;
  o.bits = bits;
  BoardSystem fast("fast", scene, so, setup(o));
  o.model = board::WrapperModel::cycle;
  BoardSystem cycle("cycle", scene, so, setup(o));
  o.clocked_lanes = rtl::rtl_lanes_factory();
  BoardSystem rtl("rtl", scene, so, setup(o));
  run_all({&fast, &cycle, &rtl});
  expect_cycle_model_matches_fast(cycle, rtl);
  expect_cycle_model_matches_fast(fast, rtl);
  EXPECT_EQ(cycle.end_time(), rtl.end_time());  // exact sc_time
  EXPECT_GT(rtl.driver().stats().fpga_busy, sc_core::SC_ZERO_TIME);
  // the lanes' answers were the RTL's: the run found blocked segments
  const SolverResult cpu = cpu_fixed_point(scene, so, bits);
  expect_identical(rtl.result().radiosity, cpu.radiosity);
}

TEST(RtlLanes, BoardRunEqualsCppLanesAt15BitsTwoLanes) {
  REQUIRE_RTL(15);
  expect_rtl_lanes_match_cpp(15, 2, 3);
}

TEST(RtlLanes, BoardRunEqualsCppLanesAt7BitsThreeLanes) {
  REQUIRE_RTL(7);
  expect_rtl_lanes_match_cpp(7, 3, 2);
}

// The guard band on t through T_GUARD into the RTL lanes' t_guard port: the same bits as the C++ lanes
// and the CPU backend with the same guard.
TEST(RtlLanes, GuardBandOnTEqualsCppLanesAt15Bits) {
  REQUIRE_RTL(15);
  const Scene scene = small_cornell_box();
  SolverOptions so = steps(3);
  so.fixes.bits = 15;
  so.fixes.t_guard = 4;
  BoardRunOptions o;
  o.lanes = 2;
  o.bits = 15;
  o.model = board::WrapperModel::cycle;
  BoardSystem cycle("cycle", scene, so, setup(o));
  o.clocked_lanes = rtl::rtl_lanes_factory();
  BoardSystem rtl("rtl", scene, so, setup(o));
  run_all({&cycle, &rtl});
  expect_cycle_model_matches_fast(cycle, rtl);
  const SolverResult cpu = cpu_fixed_point(scene, so, 15);
  expect_identical(rtl.result().radiosity, cpu.radiosity);
  EXPECT_EQ(rtl.result().blocked_segments, cpu.blocked_segments);
}

// Plugged-in lanes need the cycle-level wrapper and fixed-point lanes; a width without a model is
// refused by the factory, naming the widths built.
TEST(RtlLanes, RefusedWhereTheyDoNotApply) {
  BoardRunOptions o;
  o.clocked_lanes = rtl::rtl_lanes_factory();
  try {
    (void)make_board_setup(o);  // fast wrapper
    ADD_FAILURE() << "accepted with the fast wrapper";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("rtl lanes need the cycle-level wrapper"), std::string::npos) << e.what();
  }
  o.model = board::WrapperModel::cycle;
  o.float_format = pipeline::FloatFormat(8, 23);
  try {
    (void)make_board_setup(o);
    ADD_FAILURE() << "accepted with float lanes";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("fixed-point"), std::string::npos) << e.what();
  }
  EXPECT_THROW(rtl::rtl_lanes_factory().make(1, 8), std::invalid_argument);  // 8 bits: no model built
}

}  // namespace
}  // namespace rc::test
