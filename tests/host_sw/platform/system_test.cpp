// The whole system: the solver on the host thread, BoardVisibility driving the RC2000 model.
// Results must be bit-identical to the CPU fixed-point backend; concurrent mode must hide exactly
// the form-factor time; batching must not change a bit.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "scenes/prepare.h"
#include "tests/host_sw/platform/system_support.h"
#include "host_sw/outputs/run_report_json.h"
#include "host_sw/outputs/trace_json.h"

namespace rc::test {
namespace {

using sc_core::sc_time;

void expect_host_timeline_adds_up(const BoardSystem& s) {
  const BoardDriverStats& d = s.driver().stats();
  EXPECT_EQ(s.cpu().compute_time() + s.cpu().driver_time() + d.pci + d.waiting, s.end_time());
}

void expect_bit_identical(const Scene& scene, BoardRunOptions o, int steps_to_run) {
  const SolverOptions so = steps(steps_to_run);
  BoardSystem board("board", scene, so, setup(o));
  run_all({&board});
  const SolverResult cpu = cpu_fixed_point(scene, so, o.bits);
  EXPECT_EQ(board.result().steps, steps_to_run);
  EXPECT_EQ(board.result().blocked_segments, cpu.blocked_segments);
  EXPECT_GT(cpu.blocked_segments, 0u);
  expect_identical(board.result().radiosity, cpu.radiosity);
  expect_host_timeline_adds_up(board);
}

void expect_bit_identical(BoardRunOptions o, int steps_to_run) {
  expect_bit_identical(small_cornell_box(), o, steps_to_run);
}

TEST(BoardSystem, BitIdenticalToCpuFixedPointTwoLanes15Bits) {
  BoardRunOptions o;
  o.lanes = 2;
  o.bits = 15;
  expect_bit_identical(o, 300);
}

// Four 8-bit coordinates per word: four lanes from one X/Y/Z triple.
TEST(BoardSystem, BitIdenticalToCpuFixedPointFourLanes7Bits) {
  BoardRunOptions o;
  o.lanes = 4;
  o.bits = 7;
  expect_bit_identical(o, 200);
}

// 23-bit coordinates, one per word: the second lane reads X, Y, Z from bank 4 at 1/3 rate.
TEST(BoardSystem, BitIdenticalToCpuFixedPointSixBankVariant23Bits) {
  BoardRunOptions o;
  o.lanes = 2;
  o.bits = 23;
  o.concurrent = true;
  expect_bit_identical(o, 200);
}

// Serial and concurrent side by side. In concurrent mode the host computes the form factors while
// the board works; each pass outlasts them here, so exactly the form-factor time is hidden.
TEST(BoardSystem, ConcurrentModeOverlapsExactlyTheFormFactors) {
  const Scene scene = small_cornell_box();
  const SolverOptions so = steps(40);
  BoardRunOptions o;
  o.lanes = 2;
  BoardSystem serial("serial", scene, so, setup(o));
  o.concurrent = true;
  BoardSystem concurrent("concurrent", scene, so, setup(o));
  run_all({&serial, &concurrent});

  expect_identical(serial.result().radiosity, concurrent.result().radiosity);
  const sc_time ff = concurrent.cpu().time(HostWork::FormFactor);
  EXPECT_GT(ff, sc_core::SC_ZERO_TIME);
  EXPECT_EQ(ff, serial.cpu().time(HostWork::FormFactor));
  EXPECT_LE(concurrent.end_time(), serial.end_time());
  EXPECT_EQ(concurrent.driver().stats().overlap, ff);
  EXPECT_EQ(serial.driver().stats().overlap, sc_core::SC_ZERO_TIME);
  // Serial pays the form factors after the pass; concurrent hides them. Passes start on the next
  // device clock edge, so each pass may shift by less than one device period.
  const sc_time saved = serial.end_time() - concurrent.end_time();
  const sc_time slack = serial.board.params().timing.device_period * static_cast<double>(so.fixed_steps);
  EXPECT_LE(saved, ff + slack);
  EXPECT_GE(saved + slack, ff);
  EXPECT_EQ(serial.driver().stats().passes, static_cast<std::uint64_t>(so.fixed_steps));
  expect_host_timeline_adds_up(serial);
  expect_host_timeline_adds_up(concurrent);
}

// A composed scene (the Cornell Box with a mesh of our own placed in it, scenes/composition.h) on the
// board gives exactly the CPU fixed-point radiosity, as every scene does.
TEST(BoardSystem, ComposedSceneIsBitIdenticalToCpuFixedPoint) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "rc_composed_board";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "tetra.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
  std::ofstream(dir / "scene.json") << R"({"schema": "rc2000sim.composition/1", "room": "cornell-box",
    "meshes": [{"file": "tetra.obj", "fit_into": {"min": [340, 0, 100], "max": [500, 150, 260]},
                "material": {"reflectance": [0.8, 0.8, 0.8]}}]})";
  SceneOptions options;
  options.file = (dir / "scene.json").string();
  options.patch_levels = 1;
  const Scene scene = prepare_scene(options).scene;
  std::filesystem::remove_all(dir);
  ASSERT_EQ(scene.faces.size(), 38u + 4u);
  BoardRunOptions o;
  o.lanes = 2;
  expect_bit_identical(scene, o, 30);
}

// Small banks force batches of rays and sets of faces (sec 4.4); the result is bit-identical to
// one pass per step, and to the CPU.
TEST(BoardSystem, BatchingAtAndBeyondTheLimitsGivesIdenticalResults) {
  const Scene scene = small_cornell_box();
  const SolverOptions so = steps(60);
  const std::uint64_t F = scene.faces.size();
  BoardRunOptions o;
  o.host = "athlon-mp-2600";  // its driver uploads a face set once (the calibrated host's: every pass)
  o.lanes = 2;
  BoardSystem whole("whole", scene, so, setup(o));
  o.bank_capacity_bytes = F * 9 * 4;  // exactly one face set (own-face table in spare bank 5)
  BoardSystem at_limit("at_limit", scene, so, setup(o));
  o.bank_capacity_bytes = 256;        // 64 words: 7 faces per set, 128 rays per batch
  BoardSystem beyond("beyond", scene, so, setup(o));
  o.lanes = 3;                        // 3 lanes on 6 banks: the own-face table moves into the face bank
  o.bank_capacity_bytes = 200;        // 50 words: 5 faces (and their table entries) per set
  o.concurrent = true;
  BoardSystem beyond3("beyond3", scene, so, setup(o));
  run_all({&whole, &at_limit, &beyond, &beyond3});

  EXPECT_EQ(whole.driver().stats().face_sets, 1u);
  EXPECT_EQ(at_limit.board.layout().max_faces_per_set, F);
  EXPECT_EQ(at_limit.driver().stats().face_sets, 1u);
  EXPECT_EQ(at_limit.driver().stats().face_set_uploads, 1u);
  EXPECT_EQ(beyond.board.layout().max_faces_per_set, 7u);
  EXPECT_EQ(beyond.board.layout().max_rays_per_batch, 128u);
  EXPECT_EQ(beyond.driver().stats().face_sets, (F + 6) / 7);
  EXPECT_GE(beyond.driver().stats().max_batches_per_step, 2u);
  EXPECT_EQ(beyond3.board.layout().max_faces_per_set, 5u);
  EXPECT_FALSE(beyond3.board.layout().mask_bank.has_value());
  EXPECT_GE(beyond3.driver().stats().max_batches_per_step, 2u);

  const SolverResult cpu = cpu_fixed_point(scene, so, 15);
  expect_identical(whole.result().radiosity, cpu.radiosity);
  expect_identical(at_limit.result().radiosity, cpu.radiosity);
  expect_identical(beyond.result().radiosity, cpu.radiosity);
  expect_identical(beyond3.result().radiosity, cpu.radiosity);
}

// The cycle-level wrapper in the whole system, a few steps: same times, same results.
TEST(BoardSystem, CycleLevelModelMatchesFastModelInTheSolver) {
  const Scene scene = small_cornell_box();
  const SolverOptions so = steps(3);
  BoardRunOptions o;
  o.lanes = 2;
  BoardSystem fast("fast", scene, so, setup(o));
  o.model = board::WrapperModel::cycle;
  BoardSystem cycle("cycle", scene, so, setup(o));
  run_all({&fast, &cycle});
  expect_cycle_model_matches_fast(fast, cycle);
}

// The runner: the report, the trace document (the caller writes it) and the VCD SystemC writes as it
// simulates; once per process.
TEST(BoardRunner, ReportsTraceAndWritesVcd) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("rc_board_runner_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  BoardRunOptions o;
  o.host = "athlon-mp-2600";  // its driver moves data by DMA (the calibrated host's: programmed I/O)
  o.lanes = 2;
  o.concurrent = true;
  o.trace = true;
  o.trace_first_step = 2;
  o.trace_last_step = 3;
  o.vcd_path = (dir / "signals.vcd").string();
  int progress = 0;
  o.on_progress = [&](const StepProgress&) { ++progress; };
  const BoardRunResult r = run_radiosity_on_board(small_cornell_box(), steps(5), o);
  EXPECT_EQ(r.solver.steps, 5);
  EXPECT_EQ(progress, 5);
  const nlohmann::ordered_json report = to_json(r.report);  // the report.json document
  const auto& t = report["time"];
  EXPECT_NEAR(t["host_compute_seconds"].get<double>() + t["driver_cpu_seconds"].get<double>() +
                  t["pci_transfer_seconds"].get<double>() + t["waiting_seconds"].get<double>(),
              report["simulated_seconds"].get<double>(), 1e-12);
  EXPECT_EQ(report["capacity"]["max_rays_per_batch"], 1u << 21);
  EXPECT_EQ(report["lanes"].size(), 2u);
  EXPECT_EQ(report["banks"].size(), 6u);
  EXPECT_EQ(report["banks"][5]["role"], "own-face table");
  EXPECT_GT(report["intersections"]["tests"].get<double>(), 0);

  const nlohmann::json trace = nlohmann::json::parse(trace_json(r.trace.value()));
  std::set<std::string> tracks;
  for (const auto& e : trace["traceEvents"])
    if (e["name"] == "thread_name") tracks.insert(e["args"]["name"].get<std::string>());
  for (const char* track : {"host", "dma", "lane 0", "lane 1", "irq"}) EXPECT_TRUE(tracks.count(track)) << track;
  EXPECT_TRUE(std::filesystem::file_size(o.vcd_path) > 0);
  std::filesystem::remove_all(dir);
  // Last: a throw after a simulation leaves ASan unsure of the stack's bounds (SystemC switches
  // stacks without telling it), so nothing may follow it in the sanitizer build.
  EXPECT_THROW(run_radiosity_on_board(small_cornell_box(), steps(1), o), std::logic_error);
}

}  // namespace
}  // namespace rc::test
