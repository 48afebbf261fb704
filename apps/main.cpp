// rc2000sim: the command-line front end. libsystemc supplies main() and calls sc_main().
#include <CLI/CLI.hpp>
#include <systemc>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <new>

#include "apps/cli_options.h"
#include "apps/outputs.h"

namespace {

// SystemC prints its banner unless this is set before the library reads it (before sc_main runs).
const int kQuietSystemC = setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "1", 0);

}  // namespace

int sc_main(int argc, char** argv) {
  (void)kQuietSystemC;
  // sc_stop() at the end of a board run is expected, not news.
  sc_core::sc_report_handler::set_actions(sc_core::SC_INFO, sc_core::SC_DO_NOTHING);
  CLI::App app{"rc2000sim: a SystemC/TLM-2.0 model of the RC2000 radiosity accelerator"};
  app.require_subcommand(1);
  int exit_code = 0;
  rc::add_run_command(app, exit_code);
  rc::add_accuracy_command(app, exit_code);
  rc::add_calibrate_command(app, exit_code);
  rc::add_paper_command(app, exit_code);
  rc::add_sweep_command(app, exit_code);
  rc::add_bench_command(app, exit_code);
  rc::add_adaptive_command(app, exit_code);
  rc::add_design_command(app, exit_code);
  for (CLI::App* cmd : app.get_subcommands([](CLI::App*) { return true; })) rc::add_configs_option(*cmd);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);  // an option refused: the message names it (and why), then a usage hint
  } catch (const rc::CommandFailed& e) {
    std::fprintf(stderr, "%s\n", e.what());  // says what was and was not written (apps/outputs.h)
    return 1;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "error: out of memory (std::bad_alloc)\n");
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return exit_code;
}
