// `rc2000sim run`: one radiosity simulation from scene to report, patch table and image, with
// visibility answered in software (float or CPU fixed point) or by the simulated RC2000 board.
#pragma once

#include <functional>
#include <string>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "host_sw/platform/board_run.h"
#include "host_sw/radiosity/radiosity.h"
#include "host_sw/radiosity/render.h"
#include "host_sw/visibility/decision_sample.h"
#include "host_sw/visibility/visibility_factory.h"
#include "io/choice.h"
#include "pipeline/arithmetic.h"
#include "scenes/prepare.h"

namespace rc {

// Who answers visibility: a software backend or the simulated RC2000.
enum class Impl { software, board };
// The board's lanes: the C++ pipeline (pipeline/fixed_mt.h) or the Verilated RTL (rtl/mt_pipeline.v)
// in the cycle-level wrapper (docs/board.md, "RTL lanes").
enum class LanesImpl { cpp, rtl };

}  // namespace rc

template <>
struct rc::ChoiceNames<rc::Impl> {
  static constexpr std::string_view what = "implementation";
  static constexpr std::array<std::string_view, 2> names = {"software", "board"};
};

template <>
struct rc::ChoiceNames<rc::LanesImpl> {
  static constexpr std::string_view what = "lanes implementation";
  static constexpr std::array<std::string_view, 2> names = {"cpp", "rtl"};
};

namespace rc {

struct RunOptions {
  SceneOptions scene;
  SolverOptions solver;              // resolved from SolverCli
  Impl impl = Impl::software;
  SoftwareVisibility visibility = SoftwareVisibility::float_double;  // software runs' backend
  pipeline::Arithmetic arith;        // --arith, parsed once: fixed (width --bits) or float:E,M (float lanes on the board)
  bool lanes_compute = false;        // board: the lanes test every ray against every face themselves
  LanesImpl lanes_impl = LanesImpl::cpp;  // board: rtl = the Verilated RTL lanes in the cycle-level wrapper
  int bits = 15;                     // fractional bits of the fixed-point pipeline
  // --impl board: device, host, lanes, banks, cards and their split and bus, --vcd (board.vcd_path:
  // where the VCD ends up), parsed straight into it.
  BoardRunOptions board;
  std::string cpu_share;             // --cpu-share: empty (off), a fraction 0..1 or "balanced" (board.cpu_split)
  unsigned cpu_cores = 1;            // --cpu-cores: 1 or 2
  std::string ray_split = "limit";   // --ray-split: limit or nominal (board.ray_split; board/bank_layout.h)
  std::string trace_path;            // --trace: the trace.json to write (board runs)
  std::string trace_steps = "1:3";   // A:B, steps written to the trace
  std::string out_dir = "out";
  RenderOptions render;
  // The fidelity sample (host_sw/visibility/decision_sample.h): segments checked against double
  // precision (0: none) and the share of differing decisions above which the run warns.
  std::size_t fidelity_sample = kDefaultFidelitySample;
  double fidelity_warn = kDefaultFidelityWarnShare;
  bool quiet = false;
};

// `--arith TEXT` parsed (pipeline::Arithmetic::parse); a bad text is refused naming the option.
pipeline::Arithmetic parse_arith_option(const std::string& text);

// Checks `options` against what `cmd` was given: options that do not apply to this run are refused
// (CLI::ValidationError naming the option and why; docs/outputs.md, "Which options apply where").
void check_run_options(const CLI::App& cmd, const RunOptions& options);

// The run command's options registered on `cmd` (its one table of names, defaults, help and checks:
// the command line's and rc2000tlm.run()'s, python/core_module_json.cpp). The function returned, called
// after `cmd` has parsed, resolves them into RunOptions and applies check_run_options (throwing
// CLI::ValidationError naming the option, as the command line reports it).
using RunOptionsResolver = std::function<RunOptions()>;
RunOptionsResolver add_run_options(CLI::App& cmd);

// What a caller other than the command line wants from run_simulation (the Python module): whether
// the outputs are written (with the before-work checks of their paths) and the summary printed, the
// solver's steps as they end, and report.json's document (also when nothing is written).
struct RunHooks {
  bool write_outputs = true;
  bool print_summary = true;
  std::function<void(const StepProgress&, double simulated_seconds)> on_step;  // simulated: 0 for software runs
  std::function<void(const nlohmann::ordered_json&)> on_report;
};

// Computes the run, then writes its outputs (apps/outputs.h); returns the process exit code.
int run_simulation(const RunOptions& options, const RunHooks& hooks = {});

}  // namespace rc
