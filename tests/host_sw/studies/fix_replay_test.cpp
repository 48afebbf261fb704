// Timing replay (host_sw/platform/work_replay.h) of a run with segment fixes: the neighbour rule's
// host re-tests are charged as intersection tests by the solver; a recording of the run
// (record_functional_run) keeps them per step and a replay charges them too, so the design search and
// sweeps price a fixed design as a real run does (same time to the picosecond, same host work counts),
// for the software implementation and for the board.
#include <gtest/gtest.h>

#include "host_sw/platform/software_system.h"
#include "host_sw/studies/timing_study.h"
#include "tests/common/small_torus_scene.h"
#include "tests/host_sw/platform/system_support.h"

namespace rc::test {
namespace {

void expect_same_host_work(const HostCpuModel& a, const HostCpuModel& b) {
  EXPECT_EQ(a.compute_time(), b.compute_time());
  EXPECT_EQ(a.driver_time(), b.driver_time());
  for (int k = 0; k < kHostWorkKinds; ++k) EXPECT_EQ(a.count(HostWork(k)), b.count(HostWork(k))) << to_string(HostWork(k));
}

TEST(FixReplay, ReplayChargesTheNeighbourRulesReTests) {
  const Scene scene = small_torus_scene();
  const int bits = 15;
  SolverOptions so = steps(10);
  so.fixes = {bits, 2, 1, 11};
  const RecordedRun recorded = record_functional_run(scene, so, "fixed", bits, 1);
  // The recording's run is the solver's own with the fixes inside it.
  const SolverResult direct = cpu_fixed_point(scene, so, bits);
  expect_identical(recorded.result.radiosity, direct.radiosity);
  EXPECT_EQ(recorded.result.fix_tests, direct.fix_tests);
  EXPECT_EQ(recorded.result.fix_cleared, direct.fix_cleared);
  ASSERT_GT(direct.fix_cleared, 0u);
  std::uint64_t host_tests = 0;
  for (std::size_t s = 0; s < recorded.recording.steps(); ++s) host_tests += recorded.recording.host_tests(s);
  EXPECT_EQ(host_tests, direct.fix_tests);

  const HostProfile host = find_host_profile("athlon-mp-2600");
  FixedPointVisibility software_answer(bits);
  SoftwareSystem software_real("software_real", scene, so, software_answer, host);
  SoftwareSystem software_replay("software_replay", scene, so, recorded.recording, host);
  BoardRunOptions o;
  o.lanes = 2;
  o.bits = bits;
  o.concurrent = true;
  BoardSystem real("real", scene, so, setup(o));
  BoardSetup s = setup(o);
  s.replay = &recorded.recording;
  BoardSystem replayed("replayed", scene, so, s);
  run_all({&real, &replayed});
  software_real.rethrow_if_failed();
  software_replay.rethrow_if_failed();

  EXPECT_EQ(software_replay.end_time(), software_real.end_time());
  expect_same_host_work(software_replay.cpu(), software_real.cpu());
  EXPECT_EQ(replayed.end_time(), real.end_time());
  expect_same_host_work(replayed.cpu(), real.cpu());
  EXPECT_EQ(replayed.driver().stats().passes, real.driver().stats().passes);
}

}  // namespace
}  // namespace rc::test
