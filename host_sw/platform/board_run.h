// Radiosity with visibility on the simulated RC2000: the runner the command line calls, and the
// SystemC system it elaborates (a host PC whose SC_THREAD runs ProgressiveRadiosity with
// BoardVisibility and the host CPU cost model, plus the RC2000 board).
//
//   BoardRunOptions o;  o.device = "xc2v6000";  o.lanes = 2;  o.concurrent = true;
//   BoardRunResult r = run_radiosity_on_board(scene, solver_options, o);
//   r.solver   -- the SolverResult, as the software backends return it
//   r.report   -- RunReport: simulated_seconds and its parts, traffic, utilisation, capacity (docs/board.md)
//
// SystemC elaborates once per process: run_radiosity_on_board may be called once per process (a
// second call throws std::logic_error). Tests that need two systems side by side construct two
// BoardSystem modules in one elaboration instead.
#pragma once

#include <cstdint>
#include <exception>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <systemc>
#include <tlm_utils/simple_initiator_socket.h>

#include "board/board_params.h"
#include "board/rc2000.h"
#include "host_sw/energy/energy_table.h"
#include "host_sw/driver/board_visibility.h"
#include "host_sw/driver/host_cpu_model.h"
#include "host_sw/driver/multi_card_visibility.h"
#include "host_sw/radiosity/radiosity.h"
#include "host_sw/driver/trace_writer.h"
#include "host_sw/platform/card_options.h"
#include "host_sw/platform/run_report.h"
#include "host_sw/visibility/visibility_recording.h"
#include "scenes/scene.h"

namespace rc {

// Every default is `rc2000sim run --impl board`'s with no other option (apps/run_command.cpp;
// tests/scripts/library_defaults_test.sh): same device, host, lanes, banks, width and driver.
struct BoardRunOptions {
  std::string device = "xc2v6000";      // configs/devices/NAME.json, or a path to a profile
  std::optional<board::DeviceProfile> device_profile;  // when set, this profile instead of `device` (studies)
  board::LaneCount lanes = 1;           // pipeline instances (1..255, checked when set)
  unsigned banks = 0;                   // 0: the profile's bank count
  pipeline::FracBits bits = 15;         // fractional bits (7..31), checked when set
  // Set: float lanes in this format instead (docs/board.md, "Float lanes"); `bits` is then unused.
  // The oracle, if any, must then be the `float:E,M` software backend of the same format.
  std::optional<pipeline::FloatFormat> float_format;
  bool concurrent = false;              // paper sec 4.3
  // The CPU/FPGA split (host_sw/driver/cpu_split.h; one card only); off: the host profile's
  // (driver_model.cpu_*, usually off). Its answers come from the oracle, if any, else from a host
  // kernel at the lanes' width or float format that the system makes.
  CpuSplit cpu_split;
  // configs/hosts/NAME.json, or a path. The command's default: the profile fitted to the paper's
  // measurements (docs/calibration.md), so a library call gives `rc2000sim run --impl board`'s times.
  std::string host = "athlon-mp-2600-calibrated";
  std::optional<HostProfile> host_profile;  // when set, this profile instead of `host` (calibration variants)
  // Record a Chrome/Perfetto trace of steps trace_first..trace_last: BoardRunResult::trace_json (the
  // caller writes it, with its other outputs).
  bool trace = false;
  int trace_first_step = 1, trace_last_step = 3;
  // Where SystemC writes a VCD of start/busy/done/irq while the run simulates (empty: none). It is
  // written as the simulation goes, so the run command points it at a temporary file and moves that
  // into place with its other outputs when the run has succeeded.
  std::string vcd_path;
  std::uint64_t bank_capacity_bytes = 0;  // 0: the profile's (tests force batching with small banks)
  bool allow_batching = true;
  board::WrapperModel model = board::WrapperModel::fast;  // cycle: tests on small scenes only
  VisibilityBackend* oracle = nullptr;  // lanes' answer from a bit-identical host model (BoardVisibilityOptions)
  bool print_summaries = false;         // the tlm parts' one-line summaries at the end
  std::function<void(const StepProgress&)> on_progress;  // after every step (host thread)
  // Several identical cards (docs/board.md, "Several cards"): how many (1..16, checked when set),
  // how a step is split over them, and whether they share one PCI bus.
  CardCount cards = 1;
  CardSplit card_split = CardSplit::rays;
  CardBus card_bus = CardBus::shared;
};

struct BoardRunResult {
  SolverResult solver;
  RunReport report;        // to_json(report) is the report.json document
  std::string trace_json;  // BoardRunOptions::trace: the trace.json document; else empty
};

// Throws std::invalid_argument for bad options (profiles, layout, width, capacity without
// batching) and std::logic_error when called a second time in a process.
BoardRunResult run_radiosity_on_board(const Scene& scene, const SolverOptions& solver, const BoardRunOptions& options);

// ---- the system, for tests and tools that elaborate it themselves ---------------------------------

struct BoardSetup {
  board::BoardParams board;
  board::BankLayout layout;  // of `board`, made (and so checked) once, by make_board_setup
  HostProfile host;
  BoardVisibilityOptions driver;
  int trace_first_step = 1, trace_last_step = 0;  // empty range: no trace
  bool stop_when_done = true;                      // sc_stop() when the solver has finished
  // Timing replay (work_replay.h): the host replays this recording's work instead of running the
  // solver, and the board runs the same passes without data. The result then has no radiosity.
  const VisibilityRecording* replay = nullptr;
  std::function<void(const StepProgress&)> on_progress;
  CardCount cards = 1;  // identical cards, each `board`
  CardSplit card_split = CardSplit::rays;
  CardBus card_bus = CardBus::shared;
  energy::EnergyTables energy;  // the device's and host's energy tables, or why there are none
};

// Loads the profiles and checks the options (throws std::invalid_argument).
BoardSetup make_board_setup(const BoardRunOptions& options);

// One card: the host PC and one RC2000, its driver on the host thread. Several cards (setup.cards):
// identical RC2000s, each with its own PCI bus (its BARs) and a host PCI master of its own; with
// CardBus::shared the buses share card 0's arbitration (tlm/pci_bus.h), so they are one bus in
// time; the solver talks to MultiCardVisibility, whose driver threads run the cards.
class BoardSystem : public sc_core::sc_module {
 public:
  tlm_utils::simple_initiator_socket<BoardSystem> host_out;  // the host CPU's PCI master of card 0

 private:
  std::vector<std::unique_ptr<board::Rc2000>> m_cards;  // before `board`, which is card 0

 public:
  board::Rc2000& board;  // card 0 (the only one unless setup.cards > 1)

  BoardSystem(const sc_core::sc_module_name& name, const Scene& scene, const SolverOptions& solver,
              const BoardSetup& setup);

  bool finished() const { return m_finished; }
  void rethrow_if_failed() const;
  const SolverResult& result() const { return m_result; }
  sc_core::sc_time end_time() const { return m_end; }  // when the host thread finished
  const HostCpuModel& cpu() const { return m_cpu; }     // the solver's processor
  const BoardVisibility& driver() const { return card_driver(0); }
  unsigned cards() const { return static_cast<unsigned>(m_cards.size()); }
  board::Rc2000& card(unsigned c) { return *m_cards.at(c); }
  const board::Rc2000& card(unsigned c) const { return *m_cards.at(c); }
  const BoardVisibility& card_driver(unsigned c) const;
  const HostCpuModel& card_cpu(unsigned c) const;  // the processor card c's driver runs on
  const MultiCardVisibility* multi_card() const { return m_multi.get(); }  // null with one card
  TraceWriter& trace_writer() { return m_trace; }  // not trace(): sc_object::trace(sc_trace_file*) is virtual
  RunReport report(double wall_seconds = -1) const;

 private:
  void run();
  CardsReport cards_report(double total) const;

  const Scene& m_scene;
  SolverOptions m_solver;
  BoardSetup m_setup;
  HostCpuModel m_cpu;
  TraceWriter m_trace;
  std::unique_ptr<VisibilityBackend> m_cpu_kernel;  // the CPU/FPGA split's answers, when no oracle gives them
  std::unique_ptr<BoardVisibility> m_visibility;  // one card
  std::unique_ptr<MultiCardVisibility> m_multi;   // several
  std::vector<std::unique_ptr<tlm_utils::simple_initiator_socket<BoardSystem>>> m_card_out;  // cards 1..
  SolverResult m_result;
  sc_core::sc_time m_end = sc_core::SC_ZERO_TIME;
  bool m_finished = false;
  std::exception_ptr m_error;
};

}  // namespace rc
