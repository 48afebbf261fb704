// rc2000tlm._core: the thin C++ side of the Python module (python/rc2000tlm/__init__.py). Each
// function calls the library's typed API once (host_sw/platform/board_run.h, host_sw/studies/) and
// hands the result back through the JSON documents the library already writes (run report,
// sweep rows, design.json), which the Python side turns into typed objects. SystemC elaborates once per process:
// the Python side calls each of these in a fresh worker process. Errors are the library's own
// exceptions, which pybind11 raises as ValueError (std::invalid_argument) or RuntimeError, with the
// same message the command line prints.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <systemc>

#include "apps/cli_options.h"
#include "apps/run_command.h"
#include "design_module_json.h"
#include "host_sw/platform/board_run.h"
#include "host_sw/platform/run_report.h"
#include "host_sw/outputs/fidelity_json.h"
#include "host_sw/outputs/run_report_json.h"
#include "host_sw/visibility/decision_sample.h"
#include "host_sw/driver/host_cpu_model.h"
#include "host_sw/radiosity/jobs.h"
#include "host_sw/studies/calibration_variants.h"
#include "host_sw/studies/inert_axes.h"
#include "host_sw/studies/sweep_columns.h"
#include "host_sw/studies/sweep_row_json.h"
#include "host_sw/studies/paper_prediction.h"
#include "host_sw/studies/paper_workload.h"
#include "host_sw/studies/study_file.h"
#include "host_sw/studies/sweep_study.h"
#include "scenes/prepare.h"

namespace py = pybind11;

namespace {

using nlohmann::ordered_json;

// jobs= of every call: the command line's --jobs (host_sw/radiosity/jobs.h), the same check and
// message; None leaves the rule (RC2000SIM_JOBS, else the cores this process may use), whose
// variable is checked here too, before any work.
unsigned use_jobs(const std::optional<long long>& jobs) {
  if (jobs) rc::set_jobs(*jobs, "--jobs");
  return rc::jobs();
}

// A command's option table as the module shows it: by snake_case name, the default CLI11 shows (null
// where it shows none), whether it is a flag and, for a flag with one, the name that turns it off
// (--cull-receivers). The module takes exactly these names, so it and the command line cannot drift.
std::string option_table(const CLI::App& app) {
  ordered_json out;
  for (const CLI::Option* opt : app.get_options()) {
    if (opt->get_lnames().empty() || opt->get_lnames().front() == "help") continue;
    std::string name = opt->get_lnames().front();
    std::replace(name.begin(), name.end(), '-', '_');
    const std::string shown = opt->get_default_str();
    const bool flag = opt->get_expected_max() == 0;  // a flag expects no value
    out[name] = {{"flag", flag},
                 {"negation", flag && !opt->get_fnames().empty() ? ordered_json(opt->get_fnames().front()) : ordered_json()},
                 {"default", shown.empty() ? ordered_json() : ordered_json(shown)}};
  }
  return out.dump();
}

// `rc2000sim run`'s option table (apps/run_command.h, add_run_options) and every command's --configs.
std::string run_options() {
  CLI::App app{"rc2000tlm.run"};
  (void)rc::add_run_options(app);
  rc::add_configs_option(app);  // as apps/main.cpp adds it to every command
  return option_table(app);
}

// `rc2000sim sweep`'s study options (add_sweep_study_options) and --configs.
std::string sweep_options() {
  CLI::App app{"rc2000tlm.sweep"};
  (void)rc::add_sweep_study_options(app);
  rc::add_configs_option(app);
  return option_table(app);
}

// Parses `args` with `app`'s table, the command line's words for a refusal (a ValueError).
void parse_args(CLI::App& app, const std::vector<std::string>& args) {
  std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 takes its arguments last first
  app.parse(reversed);
}

// One run as `rc2000sim run ARGS` computes it: ARGS parsed by the command's own option table, checked
// by its own checks (the same messages: a refusal is a ValueError), then run_simulation. Nothing is
// written unless `write_outputs` (the module's out=); the result is report.json's document with the
// solver's steps as they ended (step, convergence_reached, simulated_seconds: null in software runs).
std::string run_cli(const std::vector<std::string>& args, bool write_outputs, bool summary) {
  CLI::App app{"rc2000tlm.run"};
  const rc::RunOptionsResolver resolve = rc::add_run_options(app);
  rc::add_configs_option(app);
  rc::RunOptions options;
  try {
    parse_args(app, args);
    options = resolve();
  } catch (const CLI::Error& e) {  // the command line's words, without its usage text
    throw std::invalid_argument(e.what());
  }
  ordered_json per_step = ordered_json::array();
  ordered_json report;
  const bool board = options.impl == rc::Impl::board;  // software runs simulate no time
  rc::RunHooks hooks;
  hooks.write_outputs = write_outputs;
  hooks.print_summary = summary;
  hooks.on_step = [&](const rc::StepProgress& p, double simulated_seconds) {
    per_step.push_back({{"step", p.step},
                        {"convergence_reached", p.convergence_reached},
                        {"simulated_seconds", board ? ordered_json(simulated_seconds) : ordered_json()}});
  };
  hooks.on_report = [&](const ordered_json& r) { report = r; };
  rc::run_simulation(options, hooks);
  report["per_step"] = per_step;
  return report.dump();
}

// A study run on this machine (run_study, which deals its timing work to worker processes of its
// own): every scene's rows as the sweep.json rows, with the scene's name and summary.
std::string study_rows(const rc::Study& study, bool progress) {
  const rc::StudyResult r = rc::run_study(study, [&](const std::string& what) {
    if (progress) std::fprintf(stderr, "\r%-78s", what.c_str());
  });
  if (progress) std::fprintf(stderr, "\r%-78s\r", "");
  const std::vector<std::string> extra = rc::extra_columns(r.study.axes);
  ordered_json out;
  out["study"] = r.study.name;
  out["scenes"] = ordered_json::array();
  for (std::size_t i = 0; i < r.scenes.size(); ++i) {
    ordered_json scene;
    scene["name"] = r.study.scenes[i].name;
    scene["faces"] = r.scenes[i].scene.faces;
    scene["patches"] = r.scenes[i].scene.patches;
    scene["rows"] = ordered_json::array();
    for (const rc::SweepRow& row : r.scenes[i].rows) scene["rows"].push_back(rc::sweep_row_json(row, extra));
    scene["warnings"] = rc::inert_axis_warnings(r.scenes[i].rows);  // as `rc2000sim sweep` prints them
    out["scenes"].push_back(scene);
  }
  return out.dump();
}

// A sweep as `rc2000sim sweep ARGS` makes its study (the command's study options, checks and words),
// run on this machine; its rows as study_rows gives them.
std::string sweep_cli(const std::vector<std::string>& args, bool progress, const std::optional<long long>& jobs) {
  use_jobs(jobs);
  CLI::App app{"rc2000tlm.sweep"};
  const std::function<rc::Study()> study_of_options = rc::add_sweep_study_options(app);
  rc::add_configs_option(app);
  rc::Study study;
  try {
    parse_args(app, args);
    study = study_of_options();
  } catch (const CLI::Error& e) {
    throw std::invalid_argument(e.what());
  }
  return study_rows(study, progress);
}

// Table 2 as `rc2000sim paper` predicts it with its defaults (the paper's table, the calibrated host
// and its variants, 15-bit bit-exact visibility): one record per scene and implementation, the
// fields of paper.json's scene records.
std::string paper_table(const std::string& host_name, bool progress, const std::optional<long long>& jobs) {
  use_jobs(jobs);
  const std::vector<rc::PaperRow> rows = rc::load_paper_table(rc::default_paper_table_path());
  const rc::HostProfile host = rc::find_host_profile(host_name);
  const std::vector<rc::CalibratedVariant> variants = rc::load_calibrated_variants(rc::default_variants_path());
  const std::vector<rc::PaperScene> scenes = rc::prepare_paper_scenes(rows, "fast", 15, [&](const std::string& what) {
    if (progress) std::fprintf(stderr, "\r%-78s", what.c_str());
  });
  if (progress) std::fprintf(stderr, "\r%-78s\r", "simulating the configurations");
  const rc::PaperPrediction r = rc::predict_paper(scenes, rows, host_name, host, variants);
  if (progress) std::fprintf(stderr, "\r%-78s\r", "");
  ordered_json out = ordered_json::array();
  for (const rc::PaperTableRow& row : rc::table_rows(r)) {
    out.push_back({{"faces", row.scene.faces},
                   {"patches", row.scene.patches},
                   {"steps", row.scene.steps},
                   {"implementation", rc::to_string(row.implementation)},
                   {"seconds", row.seconds},
                   {"role", row.calibration ? "calibration" : "prediction"},
                   {"paper_seconds", row.calibration ? ordered_json(row.paper_seconds()) : ordered_json()},
                   {"spread_min_seconds", row.spread.empty() ? ordered_json() : ordered_json(row.spread_min_seconds)},
                   {"spread_max_seconds", row.spread.empty() ? ordered_json() : ordered_json(row.spread_max_seconds)},
                   {"fpga_busy_seconds", row.fpga_busy_seconds},
                   {"speedup_vs_software", row.speedup_vs_software},
                   {"steps_per_second", row.steps_per_second}});
  }
  return out.dump();
}

}  // namespace

// libsystemc's sc_main is not called in a Python process: the simulations run without it (as
// SystemC allows when the kernel is started by sc_start from any code).
PYBIND11_MODULE(_core, m) {
  m.doc() = "rc2000tlm's C++ core: one board run or one study per call, once per process";
  m.def("run", &run_cli, py::arg("args"), py::arg("write_outputs") = false, py::arg("summary") = false,
        "One run as `rc2000sim run ARGS` (the command's option table and checks); report.json's document "
        "with per-step records, as JSON text");
  m.def("sweep", &sweep_cli, py::arg("args"), py::arg("progress") = false, py::arg("jobs") = py::none(),
        "A sweep as `rc2000sim sweep ARGS` makes it (the command's study options); its rows as JSON text");
  m.def("sweep_options", &sweep_options, "`rc2000sim sweep`'s study options by snake_case name, as JSON text");
  m.def("run_options", &run_options, "`rc2000sim run`'s options by snake_case name: default and whether a flag, as JSON text");
  m.def("study_file", [](const std::string& path, bool progress, const std::optional<long long>& jobs) {
          use_jobs(jobs);
          return study_rows(rc::load_study_file(path), progress);
        },
        py::arg("path"), py::arg("progress") = false, py::arg("jobs") = py::none(),
        "A study file (TOML, docs/studies.md) run; its rows as JSON text");
  m.def("study_text", [](const std::string& text, const std::string& name, bool progress, const std::optional<long long>& jobs) {
          use_jobs(jobs);
          return study_rows(rc::parse_study_text(text, name), progress);
        },
        py::arg("text"), py::arg("name"), py::arg("progress") = false, py::arg("jobs") = py::none(),
        "A study given as TOML text (`name` labels it in errors); its rows as JSON text");
  m.def("paper_table", &paper_table, py::arg("host") = "athlon-mp-2600-calibrated", py::arg("progress") = false,
        py::arg("jobs") = py::none(),
        "Table 2 as `rc2000sim paper` predicts it; one record per scene and implementation, as JSON text");
  m.def("design", &rc::design_search, py::arg("options"), py::arg("progress") = false,
        "`rc2000sim design` with the options given (JSON, snake_case names); design.json's document as JSON text");
  m.def("design_defaults", &rc::design_defaults, "The design search's defaults by option name, as JSON text");
  m.def("jobs", [](const std::optional<long long>& jobs) { return std::to_string(use_jobs(jobs)); }, py::arg("jobs") = py::none(),
        "The job count a call uses: jobs checked as --jobs is, or the rule's (RC2000SIM_JOBS, else the usable cores)");
}
