// Several RC2000 cards on one scene (BoardSetup::cards, host_sw/driver/multi_card_visibility.h): the answer is
// one card's bit for bit whatever the split and the bus; each card's timeline and the host thread's
// add up; on a shared bus the cards' transfers serialise, on separate buses they overlap (exact
// times from the bus and bank formulas); a timing replay takes the functional run's time exactly.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <memory>
#include <set>

#include <unistd.h>

#include "host_sw/outputs/trace_json.h"
#include "host_sw/visibility/visibility_factory.h"
#include "host_sw/visibility/visibility_recording.h"
#include "tests/host_sw/platform/system_support.h"
#include "host_sw/outputs/run_report_json.h"

namespace rc::test {
namespace {

using sc_core::sc_time;
using sc_core::SC_NS;

BoardRunOptions cards(unsigned n, CardSplit split, CardBus bus) {
  BoardRunOptions o;
  o.host = "athlon-mp-2600";  // its driver moves data by DMA (the calibrated host's: programmed I/O)
  o.cards = n;
  o.card_split = split;
  o.card_bus = bus;
  return o;
}

// The host thread: its compute (first processor) + driver + PCI + waiting (+ waiting for the second
// processor) = its end; with several cards its driver and PCI time are 0 and `waiting` is its wait
// for the cards. Each card's driver thread: driver CPU + PCI + interrupt waiting + idle = the end.
void expect_timelines_add_up(const BoardSystem& s) {
  const HostCpuModel& cpu = s.cpu();
  const MultiCardVisibility* multi = s.multi_card();
  ASSERT_NE(multi, nullptr);
  EXPECT_EQ(cpu.driver_time(), sc_core::SC_ZERO_TIME);
  EXPECT_EQ(cpu.compute_time() - cpu.second_cpu_compute() + multi->waiting() + cpu.second_cpu_wait(), s.end_time());
  for (unsigned c = 0; c < s.cards(); ++c) {
    const BoardDriverStats& d = s.card_driver(c).stats();
    EXPECT_EQ(s.card_cpu(c).driver_time() + d.pci + d.waiting + multi->idle(c, s.end_time()), s.end_time()) << "card " << c;
  }
  const RunReport r = s.report();
  EXPECT_EQ(r.time.driver_cpu, 0.0);
  EXPECT_EQ(r.time.pci_transfer, 0.0);
  EXPECT_EQ(r.board.cards.count, s.cards());
}

// Two cards, both splits, both buses, serial and concurrent, lanes computing or copying an oracle:
// every radiosity bit is one card's and the CPU fixed-point backend's; every card runs one pass a
// step (rays: each has half the segments; faces: each has every segment), and together they run
// one card's ray-face tests.
TEST(MultiCard, TwoCardsGiveOneCardsRadiosityBitForBit) {
  const Scene scene = small_cornell_box();
  const int n = 12;
  const SolverOptions so = steps(n);
  BoardRunOptions o;
  o.lanes = 2;
  BoardSystem one("one", scene, so, setup(o));
  std::vector<std::unique_ptr<BoardSystem>> two;
  FixedPointVisibility oracle(15);
  int index = 0;
  for (CardSplit split : {CardSplit::rays, CardSplit::faces}) {
    for (CardBus bus : {CardBus::shared, CardBus::separate}) {
      for (bool concurrent : {false, true}) {
        BoardRunOptions v = cards(2, split, bus);
        v.lanes = 2;
        v.concurrent = concurrent;
        two.push_back(std::make_unique<BoardSystem>(("two" + std::to_string(index++)).c_str(), scene, so, setup(v)));
      }
    }
    BoardRunOptions v = cards(2, split, CardBus::shared);  // the lanes copy the oracle's answer
    v.lanes = 2;
    v.oracle = &oracle;
    two.push_back(std::make_unique<BoardSystem>(("two" + std::to_string(index++)).c_str(), scene, so, setup(v)));
  }
  std::vector<BoardSystem*> all{&one};
  for (auto& s : two) all.push_back(s.get());
  run_all(all);

  const SolverResult cpu = cpu_fixed_point(scene, so, 15);
  expect_identical(one.result().radiosity, cpu.radiosity);
  ASSERT_GT(cpu.blocked_segments, 0u);
  for (std::size_t i = 0; i < two.size(); ++i) {
    const BoardSystem& s = *two[i];
    SCOPED_TRACE("two-card system " + std::to_string(i));
    ASSERT_EQ(s.cards(), 2u);
    expect_identical(s.result().radiosity, cpu.radiosity);
    EXPECT_EQ(s.result().blocked_segments, cpu.blocked_segments);
    std::uint64_t tests = 0;
    for (unsigned c = 0; c < 2; ++c) {
      EXPECT_EQ(s.card_driver(c).stats().passes, static_cast<std::uint64_t>(n)) << "card " << c;
      tests += s.card_driver(c).stats().tests;
    }
    EXPECT_EQ(tests, one.driver().stats().tests);
    expect_timelines_add_up(s);
  }
  // An oracle changes no time (BoardOracle.*): the copying systems take the computing ones' time.
  EXPECT_EQ(two[4]->end_time(), two[0]->end_time());  // rays, shared, serial
  EXPECT_EQ(two[9]->end_time(), two[5]->end_time());  // faces, shared, serial
  // The faces split: card 0 holds faces 0..34, card 1 faces 35..69.
  EXPECT_EQ(two[5]->multi_card()->faces(0), 35u);
  EXPECT_EQ(two[5]->multi_card()->faces(1), 35u);
  // Concurrent: the form factors are computed while the cards work.
  for (std::size_t i : {1u, 3u, 6u, 8u}) {
    EXPECT_GT(two[i]->multi_card()->overlap(), sc_core::SC_ZERO_TIME) << i;
    EXPECT_LE(two[i]->multi_card()->overlap(), two[i]->cpu().time(HostWork::FormFactor)) << i;
    EXPECT_LT(two[i]->end_time(), two[i - 1]->end_time()) << i;
  }
  // Separate buses never wait for each other; a shared bus makes some transfer wait.
  for (std::size_t i : {2u, 3u, 7u, 8u}) {
    for (unsigned c = 0; c < 2; ++c) EXPECT_EQ(two[i]->card(c).pci.report().total.wait, sc_core::SC_ZERO_TIME) << i;
    EXPECT_LE(two[i]->end_time(), two[i - 2]->end_time()) << i;
  }
  for (std::size_t i : {0u, 5u}) {
    EXPECT_GT(two[i]->card(0).pci.report().total.wait + two[i]->card(1).pci.report().total.wait, sc_core::SC_ZERO_TIME);
  }
}

// The hand-checkable case: no step, only the face upload of load_faces (a replay of zero steps),
// which every card does at time 0. Per segment, DMA: card c's driver charges FacePack x F_c and one
// driver call, then DMAs its 9 F_c words. On the RC2000 profile (64-bit 66.67 MHz PCI, 8 setup
// cycles; 32-bit banks at 100 MHz, write latency 2; bridge 2 PCI cycles) the bank sets the
// occupancy (tlm/pci_bus.h: max(transfer_time, D_t)):
//   bus     (8 + ceil(36 F_c / 8)) PCI cycles      F_c = 35: 166 cycles, 70: 323
//   D_t     2 PCI cycles + (2 + 9 F_c) x 10 ns     35: 30 ns + 3170 ns = 3200 ns, 70: 30 + 6320 = 6350 ns
// Separate buses: both uploads start at X = cpu_c and end at X + D_t. Shared: one starts at X, the
// other waits until it ends at Y = X + D_t and ends at X + 2 D_t. The host waits exactly until then.
TEST(MultiCard, FaceUploadsOverlapOnSeparateBusesAndSerialiseOnAShared) {
  const Scene scene = small_cornell_box();
  SolverOptions none;  // replay of 0 steps: load_faces and the first patch scan only
  VisibilityRecording empty;
  const HostProfile base = find_host_profile("athlon-mp-2600");
  DriverModel m = base.driver_model;
  m.cost_unit = DriverModel::CostUnit::PerSegment;
  m.transfer = DriverModel::Transfer::Dma;
  m.face_upload = DriverModel::FaceUpload::Once;
  std::vector<std::unique_ptr<BoardSystem>> systems;
  for (CardSplit split : {CardSplit::faces, CardSplit::rays}) {
    for (CardBus bus : {CardBus::separate, CardBus::shared}) {
      BoardRunOptions o = cards(2, split, bus);
      o.host_profile = with_driver_model(base, m);
      BoardSetup s = setup(o);
      s.replay = &empty;
      systems.push_back(std::make_unique<BoardSystem>(("up" + std::to_string(systems.size())).c_str(), scene, none, s));
    }
  }
  std::vector<BoardSystem*> all;
  for (auto& s : systems) all.push_back(s.get());
  run_all(all);

  const board::BoardParams& p = systems[0]->board.params();
  ASSERT_EQ(p.pci.width_bits, 64u);
  ASSERT_EQ(p.pci.setup_cycles, 8u);
  ASSERT_EQ(p.bank_write_latency, 2u);
  ASSERT_EQ(p.bridge_latency_cycles, 2u);
  ASSERT_EQ(p.timing.bank_period, sc_time(10, SC_NS));
  ASSERT_EQ(p.word_bits, 32u);
  const sc_time P = p.pci.clock_period;
  const sc_time face = base.driver[static_cast<int>(DriverWork::FacePack)];
  const sc_time call = base.driver[static_cast<int>(DriverWork::Call)];
  for (std::size_t i = 0; i < systems.size(); ++i) {
    const BoardSystem& s = *systems[i];
    SCOPED_TRACE("system " + std::to_string(i));
    const bool shared = i % 2 == 1;
    const std::uint64_t F = i < 2 ? 35 : 70;  // faces split: half the faces each; rays: all of them
    const sc_time bus_time = P * static_cast<double>(8 + (36 * F + 7) / 8);
    const sc_time d_t = P * 2.0 + sc_time(10, SC_NS) * static_cast<double>(2 + 9 * F);
    ASSERT_GT(d_t, bus_time);  // the bank sets the occupancy
    EXPECT_EQ(d_t, F == 35 ? sc_time(3200, SC_NS) : sc_time(6350, SC_NS));
    const sc_time x = sc_time::from_value(face.value() * F) + call;  // both cards' upload requests
    const sc_time y = x + d_t;                               // the first upload's end
    for (unsigned c = 0; c < 2; ++c) {
      EXPECT_EQ(s.card_cpu(c).driver_time(), x) << c;
      EXPECT_EQ(s.card(c).pci.report().total.busy, d_t) << c;
      EXPECT_EQ(s.card(c).bank(0).report().bytes_written, 36 * F) << c;
    }
    const sc_time wait0 = s.card(0).pci.report().total.wait, wait1 = s.card(1).pci.report().total.wait;
    if (shared) {
      // One card's upload waits from X to Y, the other's does not; the shared bus is free at Y + D_t.
      EXPECT_EQ(std::min(wait0, wait1), sc_core::SC_ZERO_TIME);
      EXPECT_EQ(std::max(wait0, wait1), y - x);
      EXPECT_EQ(s.board.pci.report().bus_free_at, y + d_t);
      EXPECT_EQ(s.card(1).pci.report().bus_free_at, y + d_t);
      EXPECT_EQ(s.multi_card()->waiting(), y + d_t);
    } else {
      EXPECT_EQ(wait0, sc_core::SC_ZERO_TIME);
      EXPECT_EQ(wait1, sc_core::SC_ZERO_TIME);
      for (unsigned c = 0; c < 2; ++c) EXPECT_EQ(s.card(c).pci.report().bus_free_at, y) << c;
      EXPECT_EQ(s.multi_card()->waiting(), y);
    }
    EXPECT_EQ(s.end_time(), s.multi_card()->waiting() + s.cpu().compute_time());
    expect_timelines_add_up(s);
  }
}

// Timing replay (work_replay.h) of two cards: the same time to the picosecond, the same passes,
// bus time and traffic per card, as the functional run, for both splits, both buses, serial and
// concurrent, with batching.
TEST(MultiCard, TimingReplayTakesExactlyTheFunctionalRunsTime) {
  const Scene scene = small_cornell_box();
  const SolverOptions so = steps(30);
  VisibilityRecording recording;
  {
    auto answer = make_functional_answer("fixed", 15);
    RecordingVisibility recorder(*answer, recording);
    ProgressiveRadiosity(scene, recorder, so).run();
  }
  std::vector<BoardRunOptions> variants;
  for (CardSplit split : {CardSplit::rays, CardSplit::faces}) {
    BoardRunOptions v = cards(2, split, CardBus::shared);
    variants.push_back(v);
    v.card_bus = CardBus::separate;
    v.lanes = 2;
    v.concurrent = true;
    variants.push_back(v);
    v.card_bus = CardBus::shared;
    v.bank_capacity_bytes = 128;  // batches of rays (64) and sets of faces (3) on every card
    variants.push_back(v);
  }
  {
    BoardRunOptions v = cards(3, CardSplit::faces, CardBus::shared);
    v.concurrent = true;
    DriverModel dual = find_host_profile("athlon-mp-2600").driver_model;
    dual.overlap = DriverModel::Overlap::DualCpu;
    v.host_profile = with_driver_model(find_host_profile("athlon-mp-2600"), dual);
    variants.push_back(v);
  }
  std::vector<std::unique_ptr<BoardSystem>> real, replayed;
  for (std::size_t i = 0; i < variants.size(); ++i) {
    real.push_back(std::make_unique<BoardSystem>(("real" + std::to_string(i)).c_str(), scene, so, setup(variants[i])));
    BoardSetup s = setup(variants[i]);
    s.replay = &recording;
    replayed.push_back(std::make_unique<BoardSystem>(("replay" + std::to_string(i)).c_str(), scene, so, s));
  }
  std::vector<BoardSystem*> all;
  for (auto& s : real) all.push_back(s.get());
  for (auto& s : replayed) all.push_back(s.get());
  run_all(all);

  for (std::size_t i = 0; i < real.size(); ++i) {
    SCOPED_TRACE("variant " + std::to_string(i));
    const BoardSystem &a = *real[i], &b = *replayed[i];
    EXPECT_EQ(b.end_time(), a.end_time());
    EXPECT_EQ(b.cpu().compute_time(), a.cpu().compute_time());
    EXPECT_EQ(b.multi_card()->waiting(), a.multi_card()->waiting());
    EXPECT_EQ(b.multi_card()->overlap(), a.multi_card()->overlap());
    for (unsigned c = 0; c < a.cards(); ++c) {
      const BoardDriverStats &x = a.card_driver(c).stats(), &y = b.card_driver(c).stats();
      EXPECT_EQ(y.passes, x.passes) << c;
      EXPECT_EQ(y.fpga_busy, x.fpga_busy) << c;
      EXPECT_EQ(y.pci, x.pci) << c;
      EXPECT_EQ(y.waiting, x.waiting) << c;
      EXPECT_EQ(y.bytes_to_board, x.bytes_to_board) << c;
      EXPECT_EQ(y.bytes_to_host, x.bytes_to_host) << c;
      EXPECT_EQ(y.tests, x.tests) << c;
      EXPECT_EQ(b.card_cpu(c).driver_time(), a.card_cpu(c).driver_time()) << c;
      EXPECT_EQ(b.card(c).pci.report().total.wait, a.card(c).pci.report().total.wait) << c;
    }
    expect_timelines_add_up(a);
    expect_timelines_add_up(b);
  }
  EXPECT_GE(real[2]->card_driver(0).stats().max_batches_per_step, 2u);
  EXPECT_GE(real[5]->card_driver(1).stats().face_sets, 2u);
  EXPECT_GT(real[6]->cpu().second_cpu_compute(), sc_core::SC_ZERO_TIME);
}

// The report: per-card figures and the buses (a shared bus is one bus of both cards), sums in the
// board sections, the codec keeps it all; the trace has each card's tracks.
TEST(MultiCard, ReportHasPerCardFiguresAndTheTraceATrackPerCard) {
  const Scene scene = small_cornell_box();
  BoardRunOptions o = cards(2, CardSplit::faces, CardBus::shared);
  o.concurrent = true;
  o.trace = true;  // make_board_setup takes the step range only when a trace is asked for
  o.trace_first_step = 1;
  o.trace_last_step = 2;
  BoardSystem s("board", scene, steps(3), setup(o));
  run_all({&s});
  const RunReport r = s.report(0.5);
  EXPECT_EQ(encode(decode(encode(r))), encode(r));
  const nlohmann::ordered_json j = to_json(r);
  ASSERT_TRUE(j.contains("cards"));
  EXPECT_EQ(j["cards"]["count"], 2u);
  EXPECT_EQ(j["cards"]["split"], "faces");
  EXPECT_EQ(j["cards"]["bus"], "shared");
  ASSERT_EQ(j["cards"]["buses"].size(), 1u);
  EXPECT_EQ(j["cards"]["buses"][0]["cards"].size(), 2u);
  ASSERT_EQ(j["cards"]["per_card"].size(), 2u);
  double bus_busy = 0;
  std::uint64_t passes = 0, to_board = 0;
  for (unsigned c = 0; c < 2; ++c) {
    const auto& k = j["cards"]["per_card"][c];
    EXPECT_EQ(k["card"], c);
    EXPECT_EQ(k["faces"], 35u);
    EXPECT_EQ(k["passes"], 3u);
    EXPECT_EQ(k["pci_bus_busy_seconds"].get<double>(), s.card(c).pci.report().total.busy.to_seconds());
    EXPECT_NEAR(k["driver_cpu_seconds"].get<double>() + k["pci_transfer_seconds"].get<double>() +
                    k["waiting_seconds"].get<double>() + k["idle_seconds"].get<double>(),
                j["simulated_seconds"].get<double>(), 1e-12);
    bus_busy += k["pci_bus_busy_seconds"].get<double>();
    passes += k["passes"].get<std::uint64_t>();
    to_board += k["bytes_to_board"].get<std::uint64_t>();
  }
  EXPECT_DOUBLE_EQ(j["cards"]["buses"][0]["busy_seconds"].get<double>(), bus_busy);
  EXPECT_DOUBLE_EQ(j["cards"]["buses"][0]["utilisation"].get<double>(), bus_busy / j["simulated_seconds"].get<double>());
  EXPECT_EQ(j["batching"]["passes"], passes);
  EXPECT_EQ(j["pci"]["bytes_to_board"], to_board);
  const auto& t = j["time"];
  EXPECT_NEAR(t["host_compute_seconds"].get<double>() + t["driver_cpu_seconds"].get<double>() +
                  t["pci_transfer_seconds"].get<double>() + t["waiting_seconds"].get<double>(),
              j["simulated_seconds"].get<double>(), 1e-12);

  const std::filesystem::path file = std::filesystem::temp_directory_path() / ("rc_cards_" + std::to_string(getpid()) + ".json");
  write_trace_json(s.trace_writer(), file.string());
  std::ifstream in(file);
  const nlohmann::json trace = nlohmann::json::parse(in);
  std::filesystem::remove(file);
  std::set<std::string> tracks;
  for (const auto& e : trace["traceEvents"])
    if (e["name"] == "thread_name") tracks.insert(e["args"]["name"].get<std::string>());
  for (const char* track : {"host", "card 0 host", "card 0 dma", "card 0 lane 0", "card 0 irq", "card 1 host",
                            "card 1 dma", "card 1 lane 0", "card 1 irq"}) {
    EXPECT_TRUE(tracks.count(track)) << track;
  }
}

// One card's system is what it always was: no cards section, the report of one BoardVisibility.
TEST(MultiCard, OneCardHasNoCardsSection) {
  const Scene scene = small_cornell_box();
  BoardSystem s("board", scene, steps(2), setup(BoardRunOptions{}));
  run_all({&s});
  EXPECT_EQ(s.cards(), 1u);
  EXPECT_EQ(s.multi_card(), nullptr);
  EXPECT_FALSE(to_json(s.report()).contains("cards"));
  EXPECT_THROW(s.card_driver(1), std::out_of_range);
}

TEST(CardCount, IsValidByConstruction) {
  EXPECT_EQ(CardCount(1).value(), 1u);
  EXPECT_EQ(CardCount(16u).value(), 16u);
  EXPECT_THROW(CardCount(0), std::invalid_argument);
  EXPECT_THROW(CardCount(17), std::invalid_argument);
  EXPECT_THROW(CardCount(-1), std::invalid_argument);
  EXPECT_EQ(parse_choice<CardBus>("separate"), CardBus::separate);
  EXPECT_THROW(parse_choice<CardBus>("both"), std::invalid_argument);
}

}  // namespace
}  // namespace rc::test
