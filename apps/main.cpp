// rc2000sim: the command-line front end. libsystemc supplies main() and calls sc_main().
#include <CLI/CLI.hpp>
#include <systemc>

#include <cstdio>
#include <cstdlib>
#include <exception>

#include "apps/run_command.h"

namespace {

// SystemC prints its banner unless this is set before the library reads it (before sc_main runs).
const int kQuietSystemC = setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "1", 0);

void add_run_options(CLI::App& cmd, rc::RunOptions& o, std::string& form_factor) {
  cmd.add_option("--scene", o.scene.file, "Scene file (docs/scenes.md); default: the embedded Cornell Box")
      ->check(CLI::ExistingFile);
  cmd.add_option("--faces", o.scene.face_target, "Refine to exactly this many faces first (e.g. 70 as in the paper)")
      ->check(CLI::NonNegativeNumber);
  cmd.add_option("--face-levels", o.scene.face_levels, "Split every face into 4^k faces")->check(CLI::Range(0, 8));
  cmd.add_option("--patch-levels", o.scene.patch_levels, "Split every face into 4^m patches")
      ->check(CLI::Range(0, 8))->capture_default_str();
  cmd.add_option("--convergence", o.solver.convergence, "Stop when max unshot power < (1 - c) x max emitted power")
      ->check(CLI::Range(0.0, 1.0))->capture_default_str();
  cmd.add_option("--steps", o.solver.fixed_steps, "Run exactly this many shooting steps instead")
      ->check(CLI::NonNegativeNumber);
  cmd.add_option("--form-factor", form_factor, "point (paper) or disc")
      ->check(CLI::IsMember({"point", "disc"}))->capture_default_str();
  cmd.add_option("--visibility", o.visibility, "Visibility backend: float or fixed")
      ->check(CLI::IsMember({"float", "fixed"}))->capture_default_str();
  cmd.add_option("--bits", o.bits, "Fractional bits of the fixed-point pipeline")->check(CLI::Range(7, 31))
      ->capture_default_str();
  cmd.add_option("--out", o.out_dir, "Output folder")->capture_default_str();
  cmd.add_option("--image-size", o.render.width, "Image width and height in pixels")->check(CLI::Range(16, 8192))
      ->capture_default_str();
  cmd.add_flag("--quiet", o.quiet, "No progress output");
}

}  // namespace

int sc_main(int argc, char** argv) {
  (void)kQuietSystemC;
  CLI::App app{"rc2000sim: a SystemC/TLM-2.0 model of the RC2000 radiosity accelerator"};
  app.require_subcommand(1);

  rc::RunOptions run;
  std::string form_factor = "point";
  CLI::App* run_cmd = app.add_subcommand("run", "Solve radiosity for one scene; write report.json, patches.csv, image.png");
  add_run_options(*run_cmd, run, form_factor);

  CLI11_PARSE(app, argc, argv);
  try {
    if (*run_cmd) {
      run.solver.form_factor = rc::parse_form_factor_kind(form_factor);
      run.render.height = run.render.width;
      return rc::run_simulation(run);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return 0;
}
