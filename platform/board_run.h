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

#include <nlohmann/json.hpp>
#include <systemc>
#include <tlm_utils/simple_initiator_socket.h>

#include "board/board_params.h"
#include "board/rc2000.h"
#include "host/board_visibility.h"
#include "host/host_cpu_model.h"
#include "radiosity/radiosity.h"
#include "host/trace_writer.h"
#include "platform/run_report.h"
#include "radiosity/visibility_recording.h"
#include "scenes/scene.h"

namespace rc {

struct BoardRunOptions {
  std::string device = "xc2v6000";      // configs/devices/NAME.json, or a path to a profile
  std::optional<board::DeviceProfile> device_profile;  // when set, this profile instead of `device` (studies)
  board::LaneCount lanes = 1;           // pipeline instances (1..255, checked when set)
  unsigned banks = 0;                   // 0: the profile's bank count
  pipeline::FracBits bits = 15;         // fractional bits (7..31), checked when set
  bool concurrent = false;              // paper sec 4.3
  std::string host = "athlon-mp-2600";  // configs/hosts/NAME.json, or a path
  std::optional<HostProfile> host_profile;  // when set, this profile instead of `host` (calibration variants)
  std::string trace_path;               // Chrome/Perfetto trace.json of steps trace_first..trace_last
  int trace_first_step = 1, trace_last_step = 3;
  std::string vcd_path;                 // VCD of start/busy/done/irq
  std::uint64_t bank_capacity_bytes = 0;  // 0: the profile's (tests force batching with small banks)
  bool allow_batching = true;
  board::WrapperModel model = board::WrapperModel::fast;  // cycle: tests on small scenes only
  VisibilityBackend* oracle = nullptr;  // lanes' answer from a bit-identical host model (BoardVisibilityOptions)
  bool print_summaries = false;         // the tlm parts' one-line summaries at the end
  std::function<void(const StepProgress&)> on_progress;  // after every step (host thread)
};

struct BoardRunResult {
  SolverResult solver;
  RunReport report;  // to_json(report) is the report.json document
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
};

// Loads the profiles and checks the options (throws std::invalid_argument).
BoardSetup make_board_setup(const BoardRunOptions& options);

class BoardSystem : public sc_core::sc_module {
 public:
  tlm_utils::simple_initiator_socket<BoardSystem> host_out;  // the host CPU's PCI master (registers)
  board::Rc2000 board;

  BoardSystem(const sc_core::sc_module_name& name, const Scene& scene, const SolverOptions& solver,
              const BoardSetup& setup);

  bool finished() const { return m_finished; }
  void rethrow_if_failed() const;
  const SolverResult& result() const { return m_result; }
  sc_core::sc_time end_time() const { return m_end; }  // when the host thread finished
  const HostCpuModel& cpu() const { return m_cpu; }
  const BoardVisibility& driver() const { return *m_visibility; }
  TraceWriter& trace() { return m_trace; }
  RunReport report(double wall_seconds = -1) const;

 private:
  void run();

  const Scene& m_scene;
  SolverOptions m_solver;
  BoardSetup m_setup;
  HostCpuModel m_cpu;
  TraceWriter m_trace;
  std::unique_ptr<BoardVisibility> m_visibility;
  SolverResult m_result;
  sc_core::sc_time m_end = sc_core::SC_ZERO_TIME;
  bool m_finished = false;
  std::exception_ptr m_error;
};

}  // namespace rc
