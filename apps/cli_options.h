// Command-line options shared by several rc2000sim commands, the checks that refuse options that do
// not apply (docs/outputs.md, "Which options apply where"), and the command registry.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <initializer_list>
#include <memory>
#include <string>
#include <vector>

#include "board/checked_count.h"
#include "host_sw/radiosity/radiosity.h"
#include "host_sw/studies/study.h"
#include "io/choice.h"
#include "pipeline/resource_source.h"
#include "scenes/prepare.h"

namespace rc {

// Solver options as parsed; the form factor arrives as a name and is resolved after parsing.
struct SolverCli {
  SolverOptions options;
  std::string form_factor = to_string(SolverOptions{}.form_factor);  // the library's default: analytic
  // The options, checked: --steps at least 1 and within the solver's cap, and --convergence not given
  // beside --steps (a fixed count never reads it). Throws CLI::ValidationError naming the option.
  SolverOptions resolved(const CLI::App& cmd) const;
};

void add_scene_options(CLI::App& cmd, SceneOptions& scene);
void add_solver_options(CLI::App& cmd, SolverCli& solver);
void add_bits_option(CLI::App& cmd, int& bits);
// --resources paper|synthesis: where the fixed-point lanes' slices and block multipliers come from
// (pipeline/resource_source.h; docs/pipeline.md, "Two sources of resources"). `what` prefixes the help.
CLI::Option* add_resources_option(CLI::App& cmd, pipeline::ResourceSource& source, const std::string& what = "");
// `flag` NAME sets `value` to the choice of that name (io/choice.h): the option accepts exactly the
// choice's name list and shows its default by name.
template <class E>
CLI::Option* add_choice_option(CLI::App& cmd, const std::string& flag, E& value, const std::string& help) {
  return cmd.add_option_function<std::string>(flag, [&value](const std::string& name) { value = parse_choice<E>(name); }, help)
      ->check(CLI::IsMember(choice_names<E>()))
      ->default_str(choice_name(value));
}
// `flag` N straight into a checked count (board/checked_count.h: lanes, cards): N outside the type's
// bounds, the one place they live, is refused naming the option and the range; the help shows both.
template <class Tag, unsigned Min, unsigned Max>
CLI::Option* add_count_option(CLI::App& cmd, const std::string& flag, board::CheckedCount<Tag, Min, Max>& value,
                              const std::string& help) {
  return cmd.add_option<board::CheckedCount<Tag, Min, Max>, unsigned>(flag, value, help + ", " + std::to_string(Min) + ".." + std::to_string(Max))
      ->check(CLI::Range(Min, Max))
      ->default_str(std::to_string(value.value()));
}
// --form-factor NAME, one of form_factor_names() (host_sw/radiosity/form_factor.h), its default shown; `what`
// prefixes the help ("Base point: " for bench). Resolve with parse_form_factor_kind.
CLI::Option* add_form_factor_option(CLI::App& cmd, std::string& name, const std::string& what = "");
// The same option straight into the kind (the same names, help and refusal).
CLI::Option* add_form_factor_option(CLI::App& cmd, FormFactorKind& kind, const std::string& what = "");

// A convergence target: strictly between 0 and 1 (0 stops before the first step; 1 asks for no unshot
// power at all and runs to the solver's step cap).
CLI::Validator convergence_target();

// Number checks whose messages print numbers readably (%g: CLI11's PositiveNumber printed the
// double range's bound in 309 digits) and refuse NaN and infinities (CLI11's let "nan" through, and a
// NaN --patch-size then meant "not given"):
std::string readable(double x);
// A finite number above 0 (--patch-size).
CLI::Validator positive_finite();
// A finite number in [low, high], said with readable bounds ("Value 2 not in range 0 to 1"; CLI11's
// Range printed 0.000000 and let "nan" through).
CLI::Validator finite_in_range(double low, double high);
// A whole number of at least 1 where 0 would mean "not given" (--faces 0 was taken as no --faces):
// "must be at least 1 (<meaning>); omit it ...".
CLI::Validator count_at_least_one(const std::string& meaning);

// A path the command writes (--out, --docs, --trace, --vcd, --variants-out): not empty (an empty
// --out made "/patches.csv", at the file system's root).
CLI::Validator output_path();

// Whether the user gave `option` (not its default).
inline bool given(const CLI::App& cmd, const std::string& option) { return cmd.count(option) > 0; }
// Throws CLI::ValidationError "<option> <why>", `why` a sentence's rest: "applies to --impl board only
// (...)", "must be at least 1; ...", "does not apply with --study: ...".
[[noreturn]] void refuse_option(const std::string& option, const std::string& why);
// Refuses each of `options` that was given, with the same reason.
void refuse_given(const CLI::App& cmd, std::initializer_list<const char*> options, const std::string& why);

// Each of `formats` must be a float:E,M the pipeline has; else refuses `option` with the reason.
void check_float_formats(const std::string& option, const std::vector<std::string>& formats);

// --configs DIR: where the config files are found, for this command and the processes it starts
// (io/config_dir.h; docs/outputs.md, "Config files"). Every command has it.
void add_configs_option(CLI::App& cmd);

// --jobs N: the worker processes and threads this command uses (host_sw/radiosity/jobs.h, one rule
// for every command: default RC2000SIM_JOBS, else the cores this process may use; 1..kMaxJobs). Given,
// it sets the process's count as it is parsed; not given, a bad RC2000SIM_JOBS is refused once the
// command line is parsed, before any work. `what` ends the help: what the jobs run.
CLI::Option* add_jobs_option(CLI::App& cmd, const std::string& what);

// Each command registers itself and, when chosen, stores its exit code in `exit_code`.
void add_run_command(CLI::App& app, int& exit_code);
void add_accuracy_command(CLI::App& app, int& exit_code);
void add_calibrate_command(CLI::App& app, int& exit_code);
void add_paper_command(CLI::App& app, int& exit_code);
void add_sweep_command(CLI::App& app, int& exit_code);
// The sweep command's study options on `cmd` (scene, solver, axes, backend: everything a study file
// can say), the one table of `rc2000sim sweep` and rc2000tlm.sweep(); the function returned, called
// after parsing, makes the study they describe (checked as the command checks it).
std::function<Study()> add_sweep_study_options(CLI::App& cmd);
void add_bench_command(CLI::App& app, int& exit_code);
void add_adaptive_command(CLI::App& app, int& exit_code);
void add_design_command(CLI::App& app, int& exit_code);

}  // namespace rc
