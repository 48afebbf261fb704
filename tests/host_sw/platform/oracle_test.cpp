// The lanes' answer from a host-side model (BoardVisibilityOptions::oracle) changes nothing but
// the simulator's own work: results, simulated time, traffic and counters stay bit for bit.
#include "tests/board/board_test_support.h"
#include "tests/host_sw/platform/system_support.h"

#include "host_sw/visibility/visibility_factory.h"
#include "host_sw/visibility/visibility_recording.h"

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

#include "host_sw/platform/software_system.h"

namespace rc::test {
namespace {

void expect_same_host_time(const HostCpuModel& a, const HostCpuModel& b) {
  EXPECT_EQ(a.compute_time(), b.compute_time());
  EXPECT_EQ(a.driver_time(), b.driver_time());
  for (int k = 0; k < kHostWorkKinds; ++k) EXPECT_EQ(a.count(HostWork(k)), b.count(HostWork(k))) << to_string(HostWork(k));
}

// Timing replay (work_replay.h): no solver, no data, no lanes computing, and yet the same
// simulated time to the picosecond as the real run, for the software implementation and for the
// board in serial and concurrent mode, with and without batching, paper-faithful or culled, and with
// the CPU/FPGA split (fixed and balanced, one and two processors).
TEST(TimingReplay, ReplayedWorkTakesExactlyTheRealRunsTime) {
  const Scene scene = small_cornell_box();
  SolverOptions faithful = steps(70);
  faithful.cull_receivers = false;
  SolverOptions culled = steps(70);
  VisibilityRecording faithful_rec, culled_rec;
  // Recorded as rc2000sim paper records: unneeded segments skipped, repeated shooters reused.
  for (auto [options, recording] : {std::pair{&faithful, &faithful_rec}, std::pair{&culled, &culled_rec}}) {
    auto answer = make_functional_answer("fixed", 15);
    RecordingVisibility recorder(*answer, *recording);
    ProgressiveRadiosity(scene, recorder, *options).run();
  }
  const HostProfile host = find_host_profile("athlon-mp-2600");
  FixedPointVisibility software_answer(15);
  SoftwareSystem software_real("software_real", scene, faithful, software_answer, host);
  SoftwareSystem software_replay("software_replay", scene, faithful, faithful_rec, host);

  std::vector<std::unique_ptr<BoardSystem>> real, replayed;
  BoardRunOptions o;
  const BoardRunOptions variants[] = {
      [] { BoardRunOptions v; v.lanes = 1; return v; }(),
      [] { BoardRunOptions v; v.lanes = 2; v.concurrent = true; return v; }(),
      [] { BoardRunOptions v; v.lanes = 2; v.concurrent = true; v.bank_capacity_bytes = 256; return v; }(),
      // The CPU/FPGA split (docs/board.md): fixed on the second processor, balanced on each.
      [] { BoardRunOptions v; v.lanes = 2; v.cpu_split = parse_cpu_split("0.3", 2); return v; }(),
      [] { BoardRunOptions v; v.lanes = 2; v.concurrent = true; v.cpu_split = parse_cpu_split("balanced", 1); return v; }(),
      [] {
        BoardRunOptions v;
        v.lanes = 2;
        v.concurrent = true;
        v.bank_capacity_bytes = 256;
        v.cpu_split = parse_cpu_split("balanced", 2);
        return v;
      }(),
  };
  int index = 0;
  for (const BoardRunOptions& v : variants) {
    for (auto [options, recording] : {std::pair{&faithful, &faithful_rec}, std::pair{&culled, &culled_rec}}) {
      const std::string n = std::to_string(index++);
      real.push_back(std::make_unique<BoardSystem>(("real" + n).c_str(), scene, *options, setup(v)));
      BoardSetup s = setup(v);
      s.replay = recording;
      replayed.push_back(std::make_unique<BoardSystem>(("replay" + n).c_str(), scene, *options, s));
    }
  }
  std::vector<BoardSystem*> all;
  for (auto& s : real) all.push_back(s.get());
  for (auto& s : replayed) all.push_back(s.get());
  run_all(all);
  software_real.rethrow_if_failed();
  software_replay.rethrow_if_failed();

  EXPECT_EQ(software_replay.end_time(), software_real.end_time());
  expect_same_host_time(software_replay.cpu(), software_real.cpu());
  EXPECT_GT(software_real.end_time(), sc_core::SC_ZERO_TIME);
  for (std::size_t i = 0; i < real.size(); ++i) {
    SCOPED_TRACE("variant " + std::to_string(i));
    expect_same_timing(*replayed[i], *real[i]);
    expect_same_host_time(replayed[i]->cpu(), real[i]->cpu());
    EXPECT_EQ(replayed[i]->driver().stats().passes, real[i]->driver().stats().passes);
    EXPECT_EQ(replayed[i]->driver().stats().overlap, real[i]->driver().stats().overlap);
  }
  EXPECT_GE(real[4]->driver().stats().max_batches_per_step, 2u);  // batching, paper-faithful
  EXPECT_GE(real[5]->driver().stats().max_batches_per_step, 2u);  // batching, culled
  EXPECT_GE(real[4]->driver().stats().face_sets, 2u);
  for (std::size_t i = 6; i < real.size(); ++i) {
    EXPECT_GT(real[i]->driver().stats().cpu_segments, 0u) << "variant " << i;
    EXPECT_EQ(replayed[i]->driver().stats().cpu_segments, real[i]->driver().stats().cpu_segments) << "variant " << i;
  }
}

}  // namespace
}  // namespace rc::test
