// The bound model (host_sw/platform/run_bounds.h): every figure against a hand computation on a
// report with chosen numbers, then against simulated boards (the pass-time formula's binding term,
// each bank's busy time one bank cycle a word, no resource busier than the FPGA).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <tuple>

#include "board/pass_timing.h"
#include "host_sw/platform/run_bounds.h"
#include "tests/host_sw/platform/system_support.h"

namespace rc::test {
namespace {

BankUseReport bank(unsigned index, const char* role, std::uint64_t read, std::uint64_t written, double busy) {
  BankUseReport b;
  b.bank = index;
  b.role = role;
  b.bytes_read = read;
  b.bytes_written = written;
  b.busy_seconds = busy;
  return b;
}

// 10 s simulated: host compute 4, driver 1, PCI 2, waiting 3; the FPGA busy 5 s at 50 MHz with two
// full-rate lanes (one group), 3e8 tests; 32-bit banks at 100 MHz; a 32-bit 33 MHz PCI bus.
RunReport hand_report() {
  RunReport r;
  r.board_run = true;
  r.simulated_seconds = 10;
  r.time.host_compute = 4;
  r.time.driver_cpu = 1;
  r.time.pci_transfer = 2;
  r.time.waiting = 3;
  r.time.fpga_busy = 5;
  DeviceReport& d = r.board.device;
  d.clock_hz = 50e6;
  d.bank_word_bits = 32;
  d.bank_clock_hz = 100e6;
  d.pci_width_bits = 32;
  d.pci_clock_hz = 33e6;
  r.board.layout.ray_groups = {{{1, 2, 3}, 2, 0, 1.0}};
  r.board.lanes = {{0, 1.0, 150000000, 0.6}, {1, 1.0, 150000000, 0.6}};
  r.intersections.tests = 300000000;
  r.board.banks = {bank(0, "faces", 4000000, 4000000, 0.02), bank(1, "rays g0 X", 400000000, 4000000, 1.01),
                   bank(4, "results", 800000000, 800000000, 4.0), bank(5, "spare", 0, 0, 0.0)};
  r.board.stream_limits = {{"bank 4 (results)", 30, 4.0}, {"lanes", 10, 1.0}};
  r.board.pci.bytes_to_board = 20000000;
  r.board.pci.bytes_to_host = 10000000;
  r.board.pci.dma_transfers = 5;
  r.board.pci.bus_busy_seconds = 0.5;
  return r;
}

TEST(RunBounds, EveryFigureIsTheHandComputation) {
  const RunBounds b = run_bounds(hand_report());
  ASSERT_EQ(b.resources.size(), 8u);  // lanes, four banks, PCI, host compute, driver
  const ResourceUse& lanes = b.resources[0];
  EXPECT_EQ(lanes.name, "lanes");
  EXPECT_DOUBLE_EQ(lanes.capacity, 2 * 50e6);        // two lanes, one test a cycle each
  EXPECT_DOUBLE_EQ(lanes.demand, 3e8 / 5);            // tests over the FPGA busy time
  EXPECT_DOUBLE_EQ(lanes.utilisation, 0.6);
  EXPECT_DOUBLE_EQ(lanes.busy_seconds, 3.0);
  EXPECT_DOUBLE_EQ(*lanes.tests_per_second_ceiling, 1e8);
  EXPECT_DOUBLE_EQ(b.tests_per_cycle_demand, 1.2);
  EXPECT_DOUBLE_EQ(b.tests_per_cycle_capacity, 2.0);

  const ResourceUse& results = b.resources[3];
  EXPECT_EQ(resource_label(results), "bank 4 (results, read-modify-write)");  // two lanes share a word
  EXPECT_DOUBLE_EQ(results.capacity, 4 * 100e6);
  EXPECT_DOUBLE_EQ(results.read_bytes_per_second, 8e8 / 5);
  EXPECT_DOUBLE_EQ(results.written_bytes_per_second, 8e8 / 5);
  EXPECT_DOUBLE_EQ(results.demand, 3.2e8);
  EXPECT_DOUBLE_EQ(results.utilisation, 0.8);
  EXPECT_DOUBLE_EQ(*results.tests_per_second_ceiling, 3e8 / 4.0);
  EXPECT_DOUBLE_EQ(*b.resources[2].tests_per_second_ceiling, 3e8 / 1.01);  // rays g0 X
  EXPECT_FALSE(b.resources[4].tests_per_second_ceiling.has_value());      // the spare bank did nothing

  const ResourceUse& pci = b.resources[5];
  EXPECT_EQ(resource_label(pci), "PCI (DMA)");
  EXPECT_DOUBLE_EQ(pci.capacity, 4 * 33e6);
  EXPECT_DOUBLE_EQ(pci.written_bytes_per_second, 2e7 / 10);  // to the board, over the run
  EXPECT_DOUBLE_EQ(pci.read_bytes_per_second, 1e7 / 10);
  EXPECT_DOUBLE_EQ(pci.utilisation, 0.05);
  EXPECT_DOUBLE_EQ(*pci.tests_per_second_ceiling, 3e8 / 0.5);
  EXPECT_DOUBLE_EQ(b.resources[6].utilisation, 0.4);  // host compute
  EXPECT_DOUBLE_EQ(*b.resources[7].tests_per_second_ceiling, 3e8 / 1.0);  // driver

  EXPECT_DOUBLE_EQ(b.sram_bytes_per_second, (8e6 + 4.04e8 + 1.6e9) / 5);
  EXPECT_DOUBLE_EQ(b.sram_bytes_per_test, (8e6 + 4.04e8 + 1.6e9) / 3e8);
  EXPECT_DOUBLE_EQ(b.tests_per_second, 3e7);

  // The stream: bank 4 bounded 4 of the 5 FPGA seconds; next the lowest other ceiling, the lanes'
  // 1e8 (the ray bank's is 2.97e8, the face bank's 1.5e10).
  EXPECT_EQ(b.stream_bound_name(), "bank 4 (results, read-modify-write)");
  EXPECT_DOUBLE_EQ(b.stream_bound_share, 0.8);
  EXPECT_EQ(b.stream_next_name(), "lanes");
  // The run: host compute 4 s, then waiting for the FPGA 3 s, PCI 2 s, the driver 1 s.
  ASSERT_EQ(b.run.size(), 4u);
  EXPECT_EQ(b.run[0].name, "host_compute");
  EXPECT_EQ(b.run[1].name, "fpga");
  EXPECT_EQ(b.run[2].name, "pci");
  EXPECT_EQ(b.run[3].name, "host_driver");
  EXPECT_EQ(b.summary(),
            "run: host compute 40.0% of the time (next: FPGA 30.0%); FPGA stream: bank 4 (results, "
            "read-modify-write) 80.0% busy, 7.5e+07 tests/s; next: lanes at 1e+08 tests/s");
}

TEST(RunBounds, RolesModesTiesAndSoftwareRuns) {
  RunReport r = hand_report();
  r.board.layout.ray_groups[0].lanes = 1;  // a word per lane: results are only written
  r.board.pci.pio_transfers = 3;
  r.time.waiting = 4;  // as long as host compute: the FPGA, first in the timeline's order, wins
  const RunBounds b = run_bounds(r);
  EXPECT_EQ(resource_label(b.resources[3]), "bank 4 (results, written)");
  EXPECT_EQ(resource_label(b.resources[5]), "PCI (DMA and PIO)");
  EXPECT_EQ(b.run[0].name, "fpga");
  EXPECT_EQ(b.run[1].name, "host_compute");
  r.board.stream_limits.clear();  // no pass: no stream bound
  EXPECT_EQ(run_bounds(r).stream_bound_name(), "");
  EXPECT_NE(run_bounds(r).summary().find("no FPGA pass"), std::string::npos);
  EXPECT_THROW(run_bounds(RunReport{}), std::invalid_argument);
}

// Several cards: the FPGA's figures stay sums over sums (a card's average), PCI is the busiest bus
// and the driver the busiest card's thread; the summary says "per card".
TEST(RunBounds, SeveralCardsArePerCardOnTheFpgaAndTheBusiestBusAndDriver) {
  RunReport r = hand_report();
  r.board.cards.count = 2;
  r.board.cards.buses = {{{0}, 0.75, 0.075}, {{1}, 0.25, 0.025}};
  CardReport a, b;
  a.driver_cpu_seconds = 1.5;
  b.driver_cpu_seconds = 2.5;
  r.board.cards.per_card = {a, b};
  r.time.driver_cpu = 0;  // the solver thread drives no card itself
  const RunBounds m = run_bounds(r);
  EXPECT_EQ(m.cards, 2u);
  EXPECT_DOUBLE_EQ(*m.resources[3].tests_per_second_ceiling, 3e8 / 4.0);  // unchanged: sums over sums
  EXPECT_DOUBLE_EQ(m.resources[5].busy_seconds, 0.75);                   // the busier bus
  EXPECT_DOUBLE_EQ(m.resources[7].busy_seconds, 2.5);                    // the busier driver thread
  EXPECT_NE(m.summary().find("7.5e+07 tests/s per card"), std::string::npos) << m.summary();
}

// Two boards simulated side by side: one lane (its stream bound by the lanes, sec 4.1's three banks
// a cycle) and two lanes sharing result words (bound by the result bank's read-modify-write, sec 4.2).
TEST(RunBounds, AgreeWithTheSimulatedBoards) {
  const Scene scene = small_cornell_box();
  BoardRunOptions one, two;
  one.lanes = 1;
  two.lanes = 2;
  const BoardSetup s1 = setup(one), s2 = setup(two);
  BoardSystem a("one", scene, steps(3), s1), b("two", scene, steps(3), s2);
  run_all({&a, &b});
  for (const auto& [system, setup_of, bound] :
       {std::tuple<const BoardSystem*, const BoardSetup*, const char*>{&a, &s1, "lanes"},
        {&b, &s2, "bank 4 (results, read-modify-write)"}}) {
    const RunReport report = system->report(0);
    const RunBounds m = run_bounds(report);
    SCOPED_TRACE(bound);
    EXPECT_EQ(m.stream_bound_name(), bound);
    // The pass-time formula (board/pass_timing.h) names the same term for a pass of one step's rays.
    std::string limit;
    const board::BankLayout& layout = setup_of->layout;
    (void)board::stream_cycles(layout, setup_of->board.timing, board::split_rays(layout, 1000), false, &limit);
    EXPECT_EQ(m.stream_bound()->name, limit.substr(0, limit.find(" (")));
    EXPECT_DOUBLE_EQ(m.stream_bound_share, 1.0);  // every pass of these scenes streams alike
    // The bound resource's ceiling against the simulated rate: the lanes' peak is the rate the stream
    // reaches when no pass overhead (set-up, face fetch, latency) is left; a bank's is tests over its
    // busy time. Either way above what the FPGA reached while busy, and within the overheads of it.
    EXPECT_GT(*m.stream_bound()->tests_per_second_ceiling, m.tests_per_second_while_fpga_busy);
    EXPECT_LT(*m.stream_bound()->tests_per_second_ceiling, 1.3 * m.tests_per_second_while_fpga_busy);
    const double period = 1.0 / report.board.device.bank_clock_hz;
    for (const BankUseReport& bank : report.board.banks) {
      // Every word takes a bank cycle, read or written (its capacity: a word a cycle); a face
      // record's exposed read latency and the host's DMA keep a bank busy beyond its words.
      EXPECT_GE(bank.busy_seconds * (1 + 1e-12), static_cast<double>(bank.reads + bank.writes) * period) << bank.bank;
    }
    for (const ResourceUse& u : m.resources) {
      if (!u.fpga) continue;
      EXPECT_GE(u.utilisation * (1 + 1e-12), u.demand / u.capacity) << u.name;  // one set of units
      EXPECT_LE(u.utilisation, 1.0 + 1e-12) << u.name;                         // never busier than the FPGA
      if (u.tests_per_second_ceiling) {
        EXPECT_GE(*u.tests_per_second_ceiling * (1 + 1e-12), m.tests_per_second_while_fpga_busy) << u.name;
      }
    }
    // The lanes' share is the report's per-lane utilisation (rays over busy cycles, at full rate).
    EXPECT_NEAR(m.resources[0].utilisation, report.board.lanes[0].utilisation, 1e-9);
    if (m.stream_bound()->kind == ResourceUse::Kind::lanes) {
      // Exact: one lane at full rate streams a face's rays in as many cycles as it has rays, so the
      // FPGA's busy time is the lanes' time plus each pass's fixed cycles and each face's set-up and
      // fetch (board/pass_timing.h), all faces in one set.
      const board::WrapperTiming& t = setup_of->board.timing;
      const double per_pass = t.pass_start + t.pipeline_latency + t.pass_finish;
      const double per_face = t.face_setup + board::fetch_cycles(layout, t);
      const double passes = static_cast<double>(report.board.batching.passes);
      const double overhead_cycles = passes * (per_pass + static_cast<double>(scene.faces.size()) * per_face);
      EXPECT_NEAR((report.time.fpga_busy - m.resources[0].busy_seconds) * m.clock_hz, overhead_cycles, 1e-6);
    }
    double shares = 0;
    for (const RunPart& p : m.run) shares += p.share;
    EXPECT_NEAR(shares, 1.0, 1e-12);  // the host's timeline is these four parts
  }
}

}  // namespace
}  // namespace rc::test
