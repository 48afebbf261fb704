#include "host_sw/platform/board_run.h"

#include <chrono>
#include <stdexcept>
#include <utility>

namespace rc {

BoardRunResult run_radiosity_on_board(const Scene& scene, const SolverOptions& solver, const BoardRunOptions& options) {
  static BoardSystem* system = nullptr;  // SystemC keeps elaborated modules until the process ends
  if (system != nullptr) throw std::logic_error("run_radiosity_on_board may be called once per process (SystemC elaborates once)");
  const BoardSetup setup = make_board_setup(options);
  system = new BoardSystem("rc2000sim", scene, solver, setup);
  sc_core::sc_trace_file* vcd = nullptr;
  if (!options.vcd_path.empty()) {
    std::string base = options.vcd_path;
    if (base.size() > 4 && base.substr(base.size() - 4) == ".vcd") base.resize(base.size() - 4);
    vcd = sc_core::sc_create_vcd_trace_file(base.c_str());
    sc_core::sc_trace(vcd, system->board.start_signal, "start");
    sc_core::sc_trace(vcd, system->board.busy_signal, "busy");
    sc_core::sc_trace(vcd, system->board.done_signal, "done");
    sc_core::sc_trace(vcd, system->board.irq_signal, "irq");
  }
  const auto t0 = std::chrono::steady_clock::now();
  sc_core::sc_start();
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (vcd != nullptr) sc_core::sc_close_vcd_trace_file(vcd);
  system->rethrow_if_failed();
  return {system->result(), system->report(wall),
          options.trace ? std::optional<TraceWriter>(std::move(system->trace_writer())) : std::nullopt};
}

}  // namespace rc
