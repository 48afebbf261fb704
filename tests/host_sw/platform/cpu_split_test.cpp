// The CPU/FPGA split (host_sw/driver/cpu_split.h): the host's processor(s) test a share of each
// step's segments in software while the board tests the rest. The radiosity is the same bit for bit
// whatever the split; the time follows the schedule: the CPU's tests run beside the board part, so
// the step ends with whichever finishes last. Hand-derived schedules, exact in sc_time:
//   - CPU part the critical path: making each test dearer moves the end by exactly the added test
//     time (every other charge is the same), and the board's passes lie wholly under the CPU's work;
//   - board part the critical path: a dearer test moves nothing.
#include <gtest/gtest.h>

#include "host_sw/driver/cpu_split.h"
#include "tests/host_sw/platform/system_support.h"

namespace rc::test {
namespace {

using sc_core::sc_time;

BoardRunOptions split_options(const std::string& share, unsigned cores, double test_seconds, bool concurrent = false) {
  HostProfile host = find_host_profile("athlon-mp-2600");
  host.work[static_cast<int>(HostWork::IntersectionTest)] = sc_time(test_seconds, sc_core::SC_SEC);
  BoardRunOptions o;
  o.lanes = 2;
  o.concurrent = concurrent;
  o.host_profile = host;
  o.cpu_split = parse_cpu_split(share, cores);
  return o;
}

// 10% of the segments on the second processor at 1 us a test: the CPU part (70 tests per segment,
// 70 us) is far longer than the board part (about a microsecond per segment), so it decides the
// step; at 2 us a test every step ends later by exactly the second processor's added work.
TEST(CpuSplit, SecondProcessorOnTheCriticalPathMovesTheEndByItsTests) {
  const Scene scene = small_cornell_box();
  const SolverOptions so = steps(5);
  BoardSystem a("a", scene, so, setup(split_options("0.1", 2, 1e-6)));
  BoardSystem b("b", scene, so, setup(split_options("0.1", 2, 2e-6)));
  run_all({&a, &b});

  const std::uint64_t F = scene.faces.size();
  const std::uint64_t S = a.cpu().count(HostWork::SegmentSetup);
  const BoardDriverStats& d = a.driver().stats();
  ASSERT_GT(d.cpu_segments, 0u);
  EXPECT_EQ(d.cpu_tests, d.cpu_segments * F);
  EXPECT_EQ(a.cpu().count(HostWork::IntersectionTest), d.cpu_tests);
  EXPECT_EQ(d.tests, (S - d.cpu_segments) * F);  // the board tests the rest, every face
  EXPECT_EQ(b.driver().stats().cpu_segments, d.cpu_segments);
  EXPECT_EQ(a.cpu().second_cpu_compute(), a.cpu().time(HostWork::IntersectionTest));
  EXPECT_EQ(a.cpu().time(HostWork::IntersectionTest), sc_time(1e-6, sc_core::SC_SEC) * static_cast<double>(d.cpu_tests));
  EXPECT_EQ(b.end_time() - a.end_time(), b.cpu().time(HostWork::IntersectionTest) - a.cpu().time(HostWork::IntersectionTest));
  EXPECT_GT(a.cpu().second_cpu_wait(), sc_core::SC_ZERO_TIME);  // the first processor waited for the second
  expect_identical(a.result().radiosity, b.result().radiosity);
}

// The same share on the solver's own processor, between START and the wait: the board's passes lie
// under the CPU's tests, the interrupt is never waited for, the timeline is compute + driver + PCI
// exactly, and a dearer test moves the end by exactly its added time.
TEST(CpuSplit, OneProcessorTestsWhileTheBoardWorks) {
  const Scene scene = small_cornell_box();
  const SolverOptions so = steps(5);
  BoardSystem a("a", scene, so, setup(split_options("0.1", 1, 1e-6)));
  BoardSystem b("b", scene, so, setup(split_options("0.1", 1, 2e-6)));
  run_all({&a, &b});

  const BoardDriverStats& d = a.driver().stats();
  // Each pass is under the CPU's tests from the moment the START write returned (the pass began when
  // the write reached the register, a bus write earlier) to its end.
  EXPECT_LE(d.overlap, d.fpga_busy);
  EXPECT_LT(d.fpga_busy - d.overlap, sc_time(1, sc_core::SC_US) * static_cast<double>(d.passes));
  EXPECT_EQ(d.waiting, sc_core::SC_ZERO_TIME);  // the interrupt was raised long before the wait
  EXPECT_EQ(a.cpu().second_cpu_compute(), sc_core::SC_ZERO_TIME);
  EXPECT_EQ(a.end_time(), a.cpu().compute_time() + a.cpu().driver_time() + d.pci);
  EXPECT_EQ(b.end_time() - a.end_time(), b.cpu().time(HostWork::IntersectionTest) - a.cpu().time(HostWork::IntersectionTest));
  expect_identical(a.result().radiosity, b.result().radiosity);
}

// At 0.1 ns a test the CPU part is far shorter than the board part: doubling its cost changes no time,
// and neither does the processor that runs it.
TEST(CpuSplit, HiddenCpuPartMovesNothing) {
  const Scene scene = small_cornell_box();
  const SolverOptions so = steps(5);
  BoardSystem one_a("one_a", scene, so, setup(split_options("0.1", 1, 1e-10)));
  BoardSystem one_b("one_b", scene, so, setup(split_options("0.1", 1, 2e-10)));
  BoardSystem two_a("two_a", scene, so, setup(split_options("0.1", 2, 1e-10)));
  BoardSystem two_b("two_b", scene, so, setup(split_options("0.1", 2, 2e-10)));
  run_all({&one_a, &one_b, &two_a, &two_b});

  EXPECT_EQ(one_a.end_time(), one_b.end_time());
  EXPECT_EQ(two_a.end_time(), two_b.end_time());
  EXPECT_EQ(two_a.cpu().second_cpu_wait(), sc_core::SC_ZERO_TIME);
  // Hidden either way, it does not matter which processor tests: the board part sets every step's end.
  EXPECT_EQ(one_a.end_time(), two_a.end_time());
}

// Balanced on two processors: step 1 (nothing measured) goes to the board alone; later steps give
// the CPU the share that evens the two out, which beats both the board alone and the CPU alone.
TEST(CpuSplit, BalancedBeatsEitherSideAlone) {
  const Scene scene = small_cornell_box();
  const SolverOptions so = steps(8);
  const double test = 2e-8;  // 1.4 us a segment against 70 faces: comparable to the board part
  BoardSystem board_only("board_only", scene, so, setup(split_options("0", 2, test)));
  BoardSystem cpu_only("cpu_only", scene, so, setup(split_options("1", 2, test)));
  BoardSystem balanced("balanced", scene, so, setup(split_options("balanced", 2, test)));
  run_all({&board_only, &cpu_only, &balanced});

  const std::uint64_t S = balanced.cpu().count(HostWork::SegmentSetup);
  const std::uint64_t cpu = balanced.driver().stats().cpu_segments;
  EXPECT_GT(cpu, 0u);
  EXPECT_LT(cpu, S);
  EXPECT_EQ(board_only.driver().stats().cpu_segments, 0u);
  EXPECT_EQ(cpu_only.driver().stats().cpu_segments, S);
  EXPECT_EQ(cpu_only.driver().stats().passes, 0u);
  EXPECT_LT(balanced.end_time(), board_only.end_time());
  EXPECT_LT(balanced.end_time(), cpu_only.end_time());
  expect_identical(balanced.result().radiosity, board_only.result().radiosity);
  expect_identical(balanced.result().radiosity, cpu_only.result().radiosity);
}

// Bit identity: the board's lanes compute (no oracle), the CPU's share comes from the fixed-point
// kernel at the board's width; every split, serial and concurrent, one or two processors, gives the
// radiosity of the CPU fixed-point pipeline bit for bit.
TEST(CpuSplit, RadiosityIsBitIdenticalForEverySplit) {
  const Scene scene = small_cornell_box();
  const SolverOptions so = steps(12);
  const SolverResult reference = cpu_fixed_point(scene, so, 15);
  struct Case {
    const char* share;
    unsigned cores;
    bool concurrent;
  };
  const Case cases[] = {{"0", 1, false}, {"0.3", 1, false}, {"0.5", 2, true}, {"0.97", 1, true}, {"1", 2, false},
                        {"balanced", 1, true}, {"balanced", 2, false}};
  std::vector<std::unique_ptr<BoardSystem>> systems;
  std::vector<BoardSystem*> all;
  for (const Case& c : cases) {
    BoardRunOptions o = split_options(c.share, c.cores, 5e-8, c.concurrent);
    systems.push_back(std::make_unique<BoardSystem>(("s" + std::to_string(systems.size())).c_str(), scene, so, setup(o)));
    all.push_back(systems.back().get());
  }
  run_all(all);
  for (std::size_t i = 0; i < systems.size(); ++i) {
    SCOPED_TRACE(std::string(cases[i].share) + " on " + std::to_string(cases[i].cores));
    expect_identical(systems[i]->result().radiosity, reference.radiosity);
  }
  EXPECT_GT(systems[1]->driver().stats().cpu_segments, 0u);
  EXPECT_GT(systems[5]->driver().stats().cpu_segments, 0u);
}

// One step: the CPU takes share x segments, rounded to the nearest.
TEST(CpuSplit, FixedShareOfOneStep) {
  const Scene scene = small_cornell_box();
  BoardSystem a("a", scene, steps(1), setup(split_options("0.37", 1, 1e-9)));
  run_all({&a});
  const std::uint64_t S = a.cpu().count(HostWork::SegmentSetup);
  EXPECT_EQ(a.driver().stats().cpu_segments, static_cast<std::uint64_t>(0.37 * static_cast<double>(S) + 0.5));
  EXPECT_EQ(a.cpu().count(HostWork::IntersectionTest), a.driver().stats().cpu_segments * scene.faces.size());
}

TEST(CpuSplit, SeveralCardsAreRefused) {
  BoardRunOptions o = split_options("0.5", 1, 1e-8);
  o.cards = 2;
  try {
    (void)make_board_setup(o);
    FAIL() << "a split over several cards was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("--cpu-share"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace rc::test
