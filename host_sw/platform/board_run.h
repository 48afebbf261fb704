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
//
// One job per file: board_run_options.h (what a caller chooses), board_setup.h (profiles, fit, layout,
// checked before elaboration), board_system.h (the SystemC system; its report: board_report.cpp), and
// this runner.
#pragma once

#include <optional>

#include "host_sw/driver/trace_writer.h"
#include "host_sw/platform/board_run_options.h"
#include "host_sw/platform/board_setup.h"
#include "host_sw/platform/board_system.h"
#include "host_sw/platform/run_report.h"
#include "host_sw/radiosity/radiosity.h"
#include "scenes/scene.h"

namespace rc {

struct BoardRunResult {
  SolverResult solver;
  RunReport report;                  // to_json(report) (host_sw/outputs/run_report_json.h): report.json
  std::optional<TraceWriter> trace;  // BoardRunOptions::trace: the recorded events (trace_json(*trace),
                                     // host_sw/outputs/trace_json.h: trace.json); else empty
};

// Throws std::invalid_argument for bad options (profiles, layout, width, capacity without
// batching) and std::logic_error when called a second time in a process.
BoardRunResult run_radiosity_on_board(const Scene& scene, const SolverOptions& solver, const BoardRunOptions& options);

}  // namespace rc
