#include "apps/cli_options.h"

#include <cstdio>
#include <stdexcept>

#include "host_sw/radiosity/jobs.h"
#include "io/config_dir.h"
#include "io/input_file.h"
#include "io/parse_number.h"
#include "pipeline/float_format.h"

namespace rc {

void add_configs_option(CLI::App& cmd) {
  cmd.add_option_function<std::string>(
         "--configs",
         [](const std::string& dir) {
           try {
             io::use_config_dir(dir);
           } catch (const io::InputFileError& e) {
             refuse_option("--configs", e.what());
           }
         },
         std::string("Folder of config files (devices/, hosts/, pipeline_resources.json, paper-table2.json, ...); "
                     "default: $") + io::kConfigDirVariable + ", else the build's configs/, else the installed share/rc2000tlm/configs")
      ->type_name("DIR");
}

CLI::Option* add_jobs_option(CLI::App& cmd, const std::string& what) {
  CLI::Option* opt = cmd.add_option_function<std::string>(
                            "--jobs",
                            [](const std::string& text) {
                              try {
                                const std::optional<std::int64_t> n = io::parse_integer(text);
                                if (!n) (void)parse_jobs(text, "--jobs");  // refuses it: not a whole number
                                set_jobs(*n, "--jobs");
                              } catch (const std::invalid_argument& e) {
                                throw CLI::ValidationError(e.what());
                              }
                            },
                            "Worker processes and threads, 1.." + std::to_string(kMaxJobs) + " (default: $" + kJobsVariable +
                                ", else the " + std::to_string(usable_cores()) + " cores this process may use): " + what)
                         ->type_name("N");
  cmd.parse_complete_callback([&cmd] {
    if (given(cmd, "--jobs") || !cmd.get_subcommands().empty()) return;  // `sweep merge` runs no jobs
    try {
      (void)jobs();  // a bad RC2000SIM_JOBS is refused now, not after minutes of work
    } catch (const std::invalid_argument& e) {
      throw CLI::ValidationError(e.what());
    }
  });
  return opt;
}

CLI::Validator output_path() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        return text.empty() ? "is empty: name a folder or file to write (e.g. out)" : "";
      },
      "PATH", "output path");
}

std::string readable(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", x);
  return text;
}

CLI::Validator positive_finite() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const std::optional<double> x = io::parse_finite(text);
        if (!x) return "'" + text + "' is not a finite number";
        if (!(*x > 0)) return readable(*x) + " must be positive";
        return "";
      },
      "> 0", "positive finite number");
}

CLI::Validator finite_in_range(double low, double high) {
  return CLI::Validator(
      [low, high](std::string& text) -> std::string {
        const std::optional<double> x = io::parse_finite(text);
        if (!x) return "'" + text + "' is not a finite number";
        if (*x < low || *x > high) return "Value " + readable(*x) + " not in range " + readable(low) + " to " + readable(high);
        return "";
      },
      "in [" + readable(low) + ", " + readable(high) + "]", "number in range");
}

CLI::Validator count_at_least_one(const std::string& meaning) {
  return CLI::Validator(
      [meaning](std::string& text) -> std::string {
        const std::optional<std::int64_t> n = io::parse_integer(text);
        if (!n) return "'" + text + "' is not a whole number";
        if (*n < 1) return "must be at least 1 (" + meaning + "); omit it for the scene's own faces (sweep without --scene: the "
                                       "paper's 70)";
        return "";
      },
      ">= 1", "count");
}

CLI::Validator convergence_target() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        double c = 0;
        if (!CLI::detail::lexical_cast(text, c)) return "'" + text + "' is not a number";
        if (!(c > 0 && c < 1)) {
          return text + " is not strictly between 0 and 1 (0 stops before the first step; 1 asks for no unshot power "
                        "at all and runs to the solver's step cap)";
        }
        return "";
      },
      "in (0, 1)", "convergence target");
}

void refuse_option(const std::string& option, const std::string& why) { throw CLI::ValidationError(option + " " + why); }

void refuse_given(const CLI::App& cmd, std::initializer_list<const char*> options, const std::string& why) {
  for (const char* option : options)
    if (given(cmd, option)) refuse_option(option, why);
}

void check_float_formats(const std::string& option, const std::vector<std::string>& formats) {
  for (const std::string& f : formats) {
    try {
      (void)pipeline::parse_float_format(f);
    } catch (const std::invalid_argument& e) {
      throw CLI::ValidationError(option + " " + f + ": " + e.what());
    }
  }
}

SolverOptions SolverCli::resolved(const CLI::App& cmd) const {
  if (given(cmd, "--steps")) {
    if (options.fixed_steps < 1) refuse_option("--steps", "must be at least 1; omit it to run to convergence");
    if (options.fixed_steps > options.max_steps) {
      refuse_option("--steps", std::to_string(options.fixed_steps) + " is above the solver's cap of " +
                                   std::to_string(options.max_steps) + " steps");
    }
    refuse_given(cmd, {"--convergence"}, "does not apply with --steps (a fixed step count never reads the "
                                         "convergence target); give one or the other");
  }
  SolverOptions o = options;
  o.form_factor = parse_form_factor_kind(form_factor);
  return o;
}

void add_scene_options(CLI::App& cmd, SceneOptions& scene) {
  cmd.add_option("--scene", scene.file, "Scene file (docs/scenes.md); default: the embedded Cornell Box")
      ->check(CLI::ExistingFile);
  cmd.add_option("--faces", scene.face_target, "Refine to exactly this many faces first (70: the paper's count)")
      ->check(count_at_least_one("the number of faces to refine to"));
  cmd.add_option("--face-levels", scene.face_levels, "Split every face into 4^k faces")->check(CLI::Range(0, 8));
  CLI::Option* levels = cmd.add_option("--patch-levels", scene.patch_levels, "Split every face into 4^m patches")
                            ->check(CLI::Range(0, 8))->capture_default_str();
  cmd.add_option("--patch-size", scene.patch_size,
                 "Instead of --patch-levels: split each face until its patches' edges are at most this long "
                 "(normalised units, the scene scaled into [0,1)^3; for meshes that are not grids)")
      ->check(positive_finite())->excludes(levels);
}

void add_solver_options(CLI::App& cmd, SolverCli& solver) {
  cmd.add_option("--convergence", solver.options.convergence,
                 "Stop when max unshot power < (1 - c) x max emitted power")
      ->check(convergence_target())->capture_default_str();
  cmd.add_option("--steps", solver.options.fixed_steps,
                 "Run exactly this many shooting steps instead (at least 1; without it: to --convergence)");
  add_form_factor_option(cmd, solver.form_factor);
}

namespace {

std::string form_factor_help(const std::string& what) {
  return what + "Form factor: analytic (exact from each receiver's centre to the shooter's triangle, never creates "
                "energy), point (the paper's centre-to-centre rule) or disc (docs/radiosity.md)";
}

}  // namespace

CLI::Option* add_form_factor_option(CLI::App& cmd, std::string& name, const std::string& what) {
  const auto& names = form_factor_names();
  return cmd.add_option("--form-factor", name, form_factor_help(what))
      ->check(CLI::IsMember(std::vector<std::string>(names.begin(), names.end())))
      ->capture_default_str();
}

CLI::Option* add_form_factor_option(CLI::App& cmd, FormFactorKind& kind, const std::string& what) {
  return add_choice_option(cmd, "--form-factor", kind, form_factor_help(what));
}

void add_bits_option(CLI::App& cmd, int& bits) {
  cmd.add_option("--bits", bits, "Fractional bits of the fixed-point pipeline (7..31)")->check(CLI::Range(7, 31))
      ->capture_default_str();
}

CLI::Option* add_resources_option(CLI::App& cmd, pipeline::ResourceSource& source, const std::string& what) {
  return add_choice_option(cmd, "--resources", source,
                           what + "Where the lanes' slices and block multipliers come from: paper (the paper's place-and-route "
                                  "figures, a fit through them elsewhere) or synthesis (Yosys's counts of rtl/mt_pipeline.v for "
                                  "the device's family, turned into slices by a rule fitted on the paper's points; "
                                  "docs/pipeline.md, Two sources of resources); the clock is the paper's under both");
}

}  // namespace rc
