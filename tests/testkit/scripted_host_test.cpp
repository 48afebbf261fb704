// The timing test kit (testkit/): the scripted host's register accesses and DMA take the bus times
// worked out by hand for the round board parameters, write_ahead returns the completion offset
// without waiting, run_until_finished stops at the first step boundary after the last script ends,
// and run_pass gives the CPU pipeline's answer.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "testkit/pass_script.h"
#include "testkit/scripted_host.h"
#include "tests/board/board_test_support.h"

namespace rc::board::test {
namespace {

// 64-bit PCI at 15 ns, setup 8: a 4-byte register access is (8 + 1) * 15 = 135 ns on the bus.
TEST(TestkitHost, RegisterReadTakesOneBurstOnTheBus) {
  Rc2000 board("rc2000", round_params(1));
  std::uint32_t id = 0;
  sc_time at;
  testkit::ScriptedHost host("host", board, [&](testkit::ScriptedHost& h) {
    id = h.read(reg::kId);
    at = sc_core::sc_time_stamp();
  });
  testkit::run_until_finished({&host});
  EXPECT_EQ(id, reg::kIdValue);
  EXPECT_EQ(at, sc_time(135, SC_NS));
}

// A 1 KiB burst: max((8 + 128) * 15 = 2040 ns, bridge 30 + (2 + 256) * 10 = 2610 ns) = 2610 ns each
// way, and the bytes land in the bank and come back.
TEST(TestkitHost, DmaTakesTheBridgeTimeAndMovesTheData) {
  Rc2000 board("rc2000", round_params(1));
  std::vector<std::uint8_t> data(1024), back(1024);
  for (std::size_t i = 0; i < data.size(); ++i) data[i] = static_cast<std::uint8_t>(i * 13 + 5);
  std::vector<sc_time> at;
  testkit::ScriptedHost host("host", board, [&](testkit::ScriptedHost& h) {
    h.dma(tlmx::DmaDirection::to_device, data.data(), 2, data.size());
    at.push_back(sc_core::sc_time_stamp());
    h.dma(tlmx::DmaDirection::to_host, back.data(), 2, back.size());
    at.push_back(sc_core::sc_time_stamp());
  });
  testkit::run_until_finished({&host});
  EXPECT_EQ(at, (std::vector<sc_time>{sc_time(2610, SC_NS), sc_time(5220, SC_NS)}));
  EXPECT_EQ(board.bank(2).debug_bytes(0, data.size()), data);
  EXPECT_EQ(back, data);
}

// Issued at a local offset of 100 ns, the write completes 135 ns later; simulated time stays at 0.
TEST(TestkitHost, WriteAheadReturnsTheCompletionWithoutWaiting) {
  Rc2000 board("rc2000", round_params(1));
  sc_time done, now;
  testkit::ScriptedHost host("host", board, [&](testkit::ScriptedHost& h) {
    done = h.write_ahead(reg::kRayCount, {4}, sc_time(100, SC_NS));
    now = sc_core::sc_time_stamp();
  });
  testkit::run_until_finished({&host});
  EXPECT_EQ(done, sc_time(235, SC_NS));
  EXPECT_EQ(now, sc_core::SC_ZERO_TIME);
}

// Scripts ending at 3 us and 25 us, steps of 10 us: the simulation stops at 30 us, both finished.
TEST(TestkitRun, StopsAtTheStepAfterTheLastScriptEnds) {
  Rc2000 board("rc2000", round_params(1));
  Rc2000 other("other", round_params(1));
  testkit::ScriptedHost early("early", board, [](testkit::ScriptedHost&) { sc_core::wait(sc_time(3, SC_US)); });
  testkit::ScriptedHost late("late", other, [](testkit::ScriptedHost&) { sc_core::wait(sc_time(25, SC_US)); });
  testkit::run_until_finished({&early, &late});
  EXPECT_TRUE(early.finished);
  EXPECT_TRUE(late.finished);
  EXPECT_EQ(sc_core::sc_time_stamp(), sc_time(30, SC_US));
}

// run_pass through the registers gives the CPU pipeline's flags (expected_blocked), some set and
// some not, and exactly one pass.
TEST(TestkitPass, RunPassGivesTheCpuAnswer) {
  Rc2000 board("rc2000", round_params(2));
  std::vector<PassRecord> passes;
  board.wrapper().on_pass([&](const PassRecord& r) { passes.push_back(r); });
  const testkit::PassData d = crossing_pass(40, 15, 3, 9);
  std::vector<std::uint8_t> got;
  testkit::ScriptedHost host("host", board, [&](testkit::ScriptedHost& h) { got = testkit::run_pass(h, d); });
  testkit::run_until_finished({&host});
  const std::vector<std::uint8_t> want = testkit::expected_blocked(d, 15);
  EXPECT_EQ(got, want);
  EXPECT_NE(std::count(want.begin(), want.end(), 1), 0);
  EXPECT_NE(std::count(want.begin(), want.end(), 0), 0);
  EXPECT_EQ(passes.size(), 1u);
}

}  // namespace
}  // namespace rc::board::test
