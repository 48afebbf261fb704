// Calls the library as a program would, with every option at its default: the embedded Cornell Box
// prepared with default SceneOptions, default SolverOptions and default BoardRunOptions; writes the
// run's report (to_json(RunReport), report.json's "board") and the solver's step count as JSON.
// tests/scripts/library_defaults_test.sh compares it with `rc2000sim run --impl board`'s report.json:
// the library's defaults must be the command's (issue 24).
//
//   default_board_run OUT.json
#include <cstdio>
#include <exception>
#include <string>

#include <nlohmann/json.hpp>

#include "host_sw/platform/board_run.h"
#include "io/output_file.h"
#include "scenes/prepare.h"
#include "host_sw/outputs/run_report_json.h"

int sc_main(int argc, char** argv) {  // SystemC's entry point (libsystemc has main)
  if (argc != 2) {
    std::fprintf(stderr, "usage: default_board_run OUT.json\n");
    return 2;
  }
  try {
    const rc::PreparedScene prepared = rc::prepare_scene(rc::SceneOptions{});
    const rc::BoardRunResult r = rc::run_radiosity_on_board(prepared.scene, rc::SolverOptions{}, rc::BoardRunOptions{});
    nlohmann::ordered_json out;
    out["steps"] = r.solver.steps;
    out["simulated_seconds"] = r.report.simulated_seconds;
    out["board"] = rc::to_json(r.report);
    rc::io::write_file_atomically(argv[1], out.dump(2) + "\n");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "default_board_run: %s\n", e.what());
    return 1;
  }
  return 0;
}
