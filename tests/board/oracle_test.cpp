// The lanes' answer from a host-side model (BoardVisibilityOptions::oracle) changes nothing but
// the simulator's own work: results, simulated time, traffic and counters stay bit for bit.
#include "board_test_support.h"
#include "system_support.h"

#include "host_sw/visibility_recording.h"

namespace rc::test {
namespace {

void expect_same_timing(const BoardSystem& a, const BoardSystem& b) {
  EXPECT_EQ(a.end_time(), b.end_time());
  EXPECT_EQ(a.driver().stats().fpga_busy, b.driver().stats().fpga_busy);
  EXPECT_EQ(a.driver().stats().waiting, b.driver().stats().waiting);
  EXPECT_EQ(a.driver().stats().pci, b.driver().stats().pci);
  EXPECT_EQ(a.driver().stats().bytes_to_board, b.driver().stats().bytes_to_board);
  EXPECT_EQ(a.driver().stats().tests, b.driver().stats().tests);
  for (unsigned bank = 0; bank < a.board.params().banks; ++bank) {
    EXPECT_EQ(a.board.bank(bank).report().bytes_read, b.board.bank(bank).report().bytes_read) << bank;
    EXPECT_EQ(a.board.bank(bank).report().bytes_written, b.board.bank(bank).report().bytes_written) << bank;
  }
}

// A CPU fixed-point backend as the oracle, and a recording of it replayed: both identical to the
// lanes computing every ray against every face, in serial and concurrent mode, across face sets.
TEST(BoardOracle, OracleAndReplayChangeNoResultAndNoTime) {
  const Scene scene = small_cornell_box();
  const SolverOptions so = steps(80);
  VisibilityRecording recording;
  FixedPointVisibility answer(15);
  RecordingVisibility recorder(answer, recording);
  ProgressiveRadiosity(scene, recorder, so).run();
  ASSERT_EQ(recording.steps(), 80u);

  BoardRunOptions o;
  o.lanes = 2;
  o.concurrent = true;
  o.bank_capacity_bytes = 1024;  // several face sets and ray batches per step
  BoardSystem computed("computed", scene, so, setup(o));
  FixedPointVisibility oracle(15);
  o.oracle = &oracle;
  BoardSystem with_oracle("with_oracle", scene, so, setup(o));
  ReplayVisibility replay(recording);
  o.oracle = &replay;
  BoardSystem replayed("replayed", scene, so, setup(o));
  run_all({&computed, &with_oracle, &replayed});

  expect_identical(with_oracle.result().radiosity, computed.result().radiosity);
  expect_identical(replayed.result().radiosity, computed.result().radiosity);
  expect_same_timing(with_oracle, computed);
  expect_same_timing(replayed, computed);
  EXPECT_GE(computed.driver().stats().face_sets, 2u);
}

TEST(BoardOracle, ReplayOfAnotherTrajectoryIsAnError) {
  const Scene scene = small_cornell_box();
  VisibilityRecording recording;
  FixedPointVisibility answer(15);
  RecordingVisibility recorder(answer, recording);
  ProgressiveRadiosity(scene, recorder, steps(5)).run();
  ReplayVisibility replay(recording);
  EXPECT_THROW(ProgressiveRadiosity(scene, replay, steps(6)).run(), std::logic_error);  // one step too many
}

TEST(BoardOracle, CycleLevelModelRefusesAnOracle) {
  FixedPointVisibility oracle(15);
  BoardRunOptions o;
  o.model = board::WrapperModel::cycle;
  o.oracle = &oracle;
  const Scene scene = small_cornell_box();
  EXPECT_THROW(BoardSystem("cycle", scene, steps(1), setup(o)), std::invalid_argument);
}

}  // namespace
}  // namespace rc::test
