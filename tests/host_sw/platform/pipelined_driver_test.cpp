// The pipelined driver (host_sw/driver/board_visibility_pipelined.cpp; docs/board.md, "Pipelined
// passes"). One step driven alone on a board, its every DMA, pass and read-back interval against a
// schedule computed here from the profiles' figures: the PCI burst formula (bytes, width, setup cycles,
// clock) against the banks' own time (bridge latency, bank latency, a bank cycle per word), the register
// access time, the driver's per-call and per-segment costs, the interrupt latency,
// and the pass-timing formula (board/pass_timing.h, itself tested against the cycle-level wrapper).
// The schedule's rules are the protocol's: chunk k+1 is packed and sent while chunk k runs, its START
// is held until chunk k ends, chunk k-1 is read back meanwhile, and the host learns which chunks are
// done from the interrupt and PASSES. Then: radiosity bit for bit the same for every chunk size, and
// the options refused where they do not apply.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include <tlm_utils/simple_initiator_socket.h>

#include "board/pass_timing.h"
#include "host_sw/driver/trace_writer.h"
#include "tests/host_sw/platform/system_support.h"

namespace rc::test {
namespace {

using sc_core::sc_time;

BoardSetup one_step_setup() {
  const HostProfile base = find_host_profile("athlon-mp-2600");
  DriverModel m = base.driver_model;
  m.cost_unit = DriverModel::CostUnit::PerSegment;
  m.transfer = DriverModel::Transfer::Dma;
  m.face_upload = DriverModel::FaceUpload::Once;
  BoardRunOptions o;
  o.lanes = 2;
  o.host_profile = with_driver_model(base, m);
  return make_board_setup(o);
}

// F small triangles in the unit cube and segments from below to their centroids, grouped by end face.
struct OneStepWork {
  std::vector<Triangle> faces;
  SegmentBatch batch;
};

OneStepWork one_step_work(int faces, std::size_t rays) {
  OneStepWork w;
  for (int f = 0; f < faces; ++f) {
    const double x = 0.1 + 0.8 * f / faces, y = 0.2 + 0.6 * ((f * 7) % faces) / faces, z = 0.3 + 0.5 * ((f * 3) % faces) / faces;
    w.faces.push_back({{x, y, z}, {x + 0.08, y, z + 0.02}, {x, y + 0.08, z + 0.05}});
  }
  w.batch.start = {0.5, 0.5, 0.02};
  for (std::size_t i = 0; i < rays; ++i) {
    const int f = static_cast<int>(i * faces / rays);
    const Triangle& t = w.faces[f];
    w.batch.ends.push_back((t.v0 + t.v1 + t.v2) * (1.0 / 3.0));
    w.batch.end_faces.push_back(f);
  }
  return w;
}

// The board, the host's processor and the driver; the host thread loads the faces, then drives one step.
class OneStep : public sc_core::sc_module {
 public:
  tlm_utils::simple_initiator_socket<OneStep> out;
  board::Rc2000 board;
  HostCpuModel cpu;
  TraceWriter trace{1, 1};
  std::unique_ptr<BoardVisibility> driver;
  OneStepWork work;
  sc_time step_start, end;
  std::vector<std::uint8_t> blocked;

  OneStep(const sc_core::sc_module_name& name, const BoardSetup& s, BoardVisibilityOptions options, OneStepWork w)
      : sc_core::sc_module(name), out("out"), board("rc2000", s.board, s.layout), cpu(s.host), work(std::move(w)) {
    out.bind(board.pci.in);
    BoardPorts ports{out, board.dma, board.irq, board.interface(), {}};
    ports.sideband.before_start = [this](const std::uint8_t* oracle, bool timing_only) {
      board.wrapper().set_oracle(oracle);
      board.wrapper().set_timing_only(timing_only);
    };
    driver = std::make_unique<BoardVisibility>(ports, cpu, options, &trace);
    board.wrapper().on_pass([this](const board::PassRecord& r) { driver->pass_finished(r); });
    SC_HAS_PROCESS(OneStep);
    SC_THREAD(run);
  }

  std::vector<TraceEvent> events(const std::string& track) const {
    std::vector<TraceEvent> found;
    for (const TraceEvent& e : trace.events())
      if (trace.tracks()[e.track - 1] == track && e.phase == TraceEvent::Phase::complete && e.start >= step_start)
        found.push_back(e);
    return found;
  }

 private:
  void run() {
    driver->load_faces(work.faces);
    cpu.sync();
    step_start = sc_core::sc_time_stamp();
    driver->submit(work.batch);
    driver->collect(blocked);
    cpu.sync();
    end = sc_core::sc_time_stamp();
  }
};

struct Interval {
  sc_time start, end;
};

// The step as the protocol schedules it, from the figures alone.
struct Schedule {
  std::vector<Interval> dma;     // in order: each chunk's ray banks and own-surface table, read-backs
  std::vector<Interval> passes;
  sc_time end;
};

class HandSchedule {
 public:
  HandSchedule(const BoardSetup& s, std::uint64_t faces) : s_(s), faces_(faces) {}

  // The PCI formula (tlm/pci_bus.h): bursts of at most M bytes, each S + ceil(b / W) cycles (E = 1).
  sc_time pci(std::uint64_t bytes) const {
    const tlmx::PciBusConfig& c = s_.board.pci;
    EXPECT_EQ(c.burst_efficiency, 1.0);
    const std::uint64_t W = c.width_bits / 8, M = c.max_burst_bytes;
    std::uint64_t cycles = 0;
    for (std::uint64_t left = bytes; left > 0; left -= std::min(left, M)) cycles += c.setup_cycles + (std::min(left, M) + W - 1) / W;
    return c.clock_period * static_cast<double>(cycles);
  }
  // A bank's part of a burst (tlm/sram_bank.h, tlm/router.h): the bridge's latency, then the bank's
  // latency and one bank cycle per word; the bus is held for the longer of it and the bus formula.
  sc_time bank(std::uint64_t bytes, bool write) const {
    const board::BoardParams& b = s_.board;
    const unsigned latency = write ? b.bank_write_latency : b.timing.bank_read_latency;
    return b.pci.clock_period * static_cast<double>(b.bridge_latency_cycles) +
           b.timing.bank_period * static_cast<double>(latency + bytes / (b.word_bits / 8));
  }
  sc_time burst(std::uint64_t bytes, bool write) const { return std::max(pci(bytes), bank(bytes, write)); }
  sc_time access() const { return s_.board.timing.device_period * static_cast<double>(s_.board.register_access_cycles); }
  sc_time reg(unsigned words) const { return std::max(pci(4 * words), access()); }
  sc_time cost(DriverWork w, std::uint64_t n = 1) const { return s_.host.driver[static_cast<int>(w)] * static_cast<double>(n); }
  sc_time edge(const sc_time& t) const {
    const std::uint64_t p = s_.board.timing.device_period.value();
    return sc_time::from_value((t.value() + p - 1) / p * p);
  }

  Schedule run(std::uint64_t rays, std::uint64_t chunk, sc_time t0) {
    h_ = t0;
    rays_ = rays;
    chunk_ = chunk;
    const std::uint64_t chunks = (rays + chunk - 1) / chunk;
    send(0);
    for (std::uint64_t k = 1; k < chunks; ++k) {
      send(k);
      await(k - 1);
      read(k - 1);
    }
    await(chunks - 1);
    read(chunks - 1);
    out_.end = h_;
    return out_;
  }

 private:
  std::uint64_t size(std::uint64_t k) const { return std::min(rays_, (k + 1) * chunk_) - k * chunk_; }
  // The bridge's DMA engine: bursts of at most max_burst_bytes, one after the other.
  void dma(std::uint64_t bytes, bool write = true) {
    h_ += cost(DriverWork::Call);
    const sc_time start = h_;
    const std::uint64_t M = s_.board.pci.max_burst_bytes;
    for (std::uint64_t left = bytes; left > 0; left -= std::min(left, M)) h_ += burst(std::min(left, M), write);
    out_.dma.push_back({start, h_});
  }

  void send(std::uint64_t k) {
    const board::BankLayout& L = s_.layout;
    const std::uint64_t n = size(k);
    h_ += cost(DriverWork::SegmentPack, n);
    const board::RaySplit split = board::split_rays(L, n);
    std::vector<std::uint64_t> words(L.banks_available, 0);
    for (std::size_t g = 0; g < L.groups.size(); ++g)
      for (unsigned j = 0; j < L.groups[g].k(); ++j)
        words[L.groups[g].banks[j]] += board::group_bank_words(L.groups[g], j, split.packets[g]);
    for (std::uint64_t w : words)
      if (w != 0) dma(w * 4);
    dma(faces_ * 4);  // the own-surface table
    h_ += cost(DriverWork::Call);
    h_ += reg(8) + reg(3);  // RAY_COUNT..MASK_START, RAY_BASE..TABLE_BASE
    const sc_time start_written = h_ + access();
    h_ += reg(1);
    const sc_time after = out_.passes.empty() ? start_written : std::max(start_written, out_.passes.back().end);
    const std::uint64_t cycles = board::pass_timing(L, s_.board.timing, split, faces_, true).total;
    out_.passes.push_back({edge(after), edge(after) + s_.board.timing.device_period * static_cast<double>(cycles)});
  }

  // The line as the host sees it: raised by the first pass that ended after the last acknowledge, the
  // interrupt latency later. Each wake: read STATUS, acknowledge, sync, read PASSES.
  void await(std::uint64_t k) {
    h_ += cost(DriverWork::Call);
    while (done_ < k + 1) {
      const auto raiser = std::find_if(out_.passes.begin(), out_.passes.end(),
                                       [&](const Interval& p) { return p.end > last_ack_; });
      EXPECT_NE(raiser, out_.passes.end());
      h_ = std::max(h_, raiser->end + s_.board.irq_latency);
      h_ += reg(1);
      last_ack_ = h_ + access();
      h_ += reg(1);
      done_ = static_cast<std::uint64_t>(std::count_if(out_.passes.begin(), out_.passes.end(),
                                                       [&](const Interval& p) { return p.end <= h_; }));
      h_ += reg(1);
    }
  }

  void read(std::uint64_t k) {
    dma(board::split_rays(s_.layout, size(k)).result_words * 4, false);
    h_ += cost(DriverWork::ResultUnpack, size(k));
  }

  const BoardSetup& s_;
  std::uint64_t faces_;
  std::uint64_t rays_ = 0, chunk_ = 1, done_ = 0;
  sc_time h_, last_ack_;
  Schedule out_;
};

void expect_schedule(const OneStep& run, const Schedule& expected) {
  const std::vector<TraceEvent> dma = run.events("dma");
  const std::vector<TraceEvent> passes = run.events("lane 0");
  ASSERT_EQ(dma.size(), expected.dma.size());
  ASSERT_EQ(passes.size(), expected.passes.size());
  for (std::size_t i = 0; i < dma.size(); ++i) {
    EXPECT_EQ(dma[i].start, expected.dma[i].start) << "transfer " << i << " (" << dma[i].name << ")";
    EXPECT_EQ(dma[i].end, expected.dma[i].end) << "transfer " << i << " (" << dma[i].name << ")";
  }
  for (std::size_t i = 0; i < passes.size(); ++i) {
    EXPECT_EQ(passes[i].start, expected.passes[i].start) << "pass " << i;
    EXPECT_EQ(passes[i].end, expected.passes[i].end) << "pass " << i;
  }
  EXPECT_EQ(run.end, expected.end);
}

std::vector<std::uint8_t> fixed_answer(const OneStepWork& w) {
  FixedPointVisibility v(15);
  v.load_faces(w.faces);
  std::vector<std::uint8_t> blocked;
  v.submit(w.batch);
  v.collect(blocked);
  return blocked;
}

BoardVisibilityOptions chunks_of(std::size_t rays) {
  BoardVisibilityOptions o;
  o.chunk_rays = rays;
  return o;
}

// Two chunks of 64 rays against 40 faces: each pass (about 32 x 40 cycles) is far longer than sending
// a chunk, so chunk 1 is sent and its START held while chunk 0 runs, and it starts on the edge chunk 0
// ends: the passes are back to back.
TEST(PipelinedDriver, TwoChunksMatchTheHandSchedule) {
  const BoardSetup s = one_step_setup();
  OneStep run("run", s, chunks_of(64), one_step_work(40, 128));
  sc_core::sc_start();
  const Schedule expected = HandSchedule(s, 40).run(128, 64, run.step_start);
  expect_schedule(run, expected);
  ASSERT_EQ(expected.passes.size(), 2u);
  EXPECT_EQ(expected.passes[1].start, expected.passes[0].end);
  EXPECT_EQ(run.blocked, fixed_answer(run.work));
  EXPECT_EQ(run.driver->stats().passes, 2u);
}

// Three chunks, the last one short (50 + 50 + 20 rays) against 3 faces: a pass is shorter than a
// chunk's transfers, so the passes wait for their START, and chunk 0's read-back falls between
// chunk 1's and chunk 2's sends.
TEST(PipelinedDriver, ThreeChunksMatchTheHandSchedule) {
  const BoardSetup s = one_step_setup();
  OneStep run("run", s, chunks_of(50), one_step_work(3, 120));
  sc_core::sc_start();
  const Schedule expected = HandSchedule(s, 3).run(120, 50, run.step_start);
  expect_schedule(run, expected);
  ASSERT_EQ(expected.passes.size(), 3u);
  EXPECT_GT(expected.passes[1].start, expected.passes[0].end);
  EXPECT_EQ(run.blocked, fixed_answer(run.work));
  EXPECT_EQ(run.driver->stats().passes, 3u);
  EXPECT_EQ(run.driver->stats().ray_batches, 3u);
}

// A chunk beyond half a bank is refused at load, naming the largest that fits.
TEST(PipelinedDriver, ChunkBeyondHalfABankIsRefused) {
  const BoardSetup s = one_step_setup();
  OneStep run("run", s, chunks_of(s.layout.max_rays_per_batch), one_step_work(3, 10));
  try {
    run.driver->load_faces(run.work.faces);
    FAIL() << "a chunk of a whole batch was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("--chunk-rays"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("at most"), std::string::npos) << e.what();
  }
}

TEST(PipelinedDriver, SeveralCardsAreRefused) {
  BoardRunOptions o;
  o.chunk_rays = 64;
  o.cards = 2;
  EXPECT_THROW(make_board_setup(o), std::invalid_argument);
}

// The lanes compute (no oracle); every chunk size, serial and concurrent, gives the CPU fixed-point
// pipeline's radiosity bit for bit, and so does the cycle-level wrapper at one size.
TEST(PipelinedDriver, RadiosityIsBitIdenticalForEveryChunkSize) {
  const Scene scene = small_cornell_box();
  const SolverOptions so = steps(6);
  const SolverResult reference = cpu_fixed_point(scene, so, 15);
  struct Case {
    std::size_t chunk;
    bool concurrent;
    board::WrapperModel model;
  };
  const Case cases[] = {{1, false, board::WrapperModel::fast},   {7, false, board::WrapperModel::fast},
                        {64, true, board::WrapperModel::fast},   {113, false, board::WrapperModel::fast},
                        {1000, true, board::WrapperModel::fast}, {37, false, board::WrapperModel::cycle}};
  std::vector<std::unique_ptr<BoardSystem>> systems;
  std::vector<BoardSystem*> all;
  for (const Case& c : cases) {
    BoardRunOptions o;
    o.lanes = 2;
    o.chunk_rays = c.chunk;
    o.concurrent = c.concurrent;
    o.model = c.model;
    systems.push_back(std::make_unique<BoardSystem>(("s" + std::to_string(systems.size())).c_str(), scene, so, setup(o)));
    all.push_back(systems.back().get());
  }
  run_all(all);
  for (std::size_t i = 0; i < systems.size(); ++i) {
    SCOPED_TRACE("chunks of " + std::to_string(cases[i].chunk));
    expect_identical(systems[i]->result().radiosity, reference.radiosity);
    EXPECT_GT(systems[i]->driver().stats().passes, 0u);
  }
}

}  // namespace
}  // namespace rc::test
