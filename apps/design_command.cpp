// `rc2000sim design` (issue 25, docs/design.md): the fastest feasible design of one device for one
// workload, and the Pareto front of time, energy, banks and error, every figure simulated
// (host_sw/studies/design_search.h). Writes design.json, design.csv, design.md, roofline.csv,
// best-device.json (the best design's profile, for `rc2000sim run --device`) and two plots.
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

#include "apps/cli_options.h"
#include "apps/design_document.h"
#include "apps/outputs.h"
#include "apps/plot.h"
#include "apps/progress.h"
#include "apps/report.h"
#include "host_sw/studies/workload.h"
#include "host_sw/studies/paper_workload.h"
#include "profiles/profile_json.h"

namespace rc {

namespace {

// What the command adds to the search's options (host_sw/studies/design_options.h, their one home).
struct DesignCli {
  DesignOptions options;
  int steps = 0;  // --steps as given (design_steps makes it the workload's fixed count)
  std::string ray_split = "limit";  // --ray-split (options.space.ray_split)
  bool quiet = false;
  std::string out_dir = "out/design";
  std::string command = "rc2000sim design";  // as given, for design.md
};

// The command line as given (every option that was), for the page that records it.
std::string given_command(const CLI::App& cmd) {
  std::string text = "rc2000sim design";
  for (const CLI::Option* opt : cmd.get_options()) {
    if (opt->count() == 0 || opt->get_name() == "--help" || opt->get_name() == "--quiet") continue;
    text += " " + opt->get_name();
    if (opt->get_expected_min() > 0)
      for (const std::string& value : opt->results()) text += " " + value;
  }
  return text;
}

// The values given, checked where both front ends check them (design_options.h), then the axes
// resolved; a refusal is the command line's (named option, usage hint).
void check_and_resolve(const CLI::App& cmd, DesignCli& cli) {
  DesignOptions& o = cli.options;
  try {
    if (given(cmd, "--steps")) o.workload.steps = design_steps(cli.steps);
    o.space.ray_split = board::parse_ray_split(cli.ray_split);
    // A scene file as it is, solved with run's form factor, unless told otherwise (workload.h).
    take_scene_as_given(o.workload.scene, [&](const std::string& option) { return given(cmd, option); });
    if (!o.workload.scene.file.empty() && !given(cmd, "--form-factor")) o.workload.form_factor = kSceneFileFormFactor;
    if (given(cmd, "--max-banks")) check_design_max_banks(o.constraints.max_banks);
    if (given(cmd, "--min-bits")) check_design_min_bits(o.constraints.min_bits);
    if (given(cmd, "--max-energy")) check_design_cap("--max-energy", o.constraints.max_energy_joules);
    if (given(cmd, "--max-power")) check_design_cap("--max-power", o.constraints.max_watts);
    if (given(cmd, "--max-error")) check_design_cap("--max-error", o.constraints.max_error);
    if (given(cmd, "--max-error-max")) check_design_cap("--max-error-max", o.constraints.max_error_max);
    for (const auto& [option, text] : {std::pair<const char*, const std::string&>{"--lanes", o.lanes}, {"--banks", o.banks},
                                       {"--bank-clocks", o.bank_clocks}, {"--offset-lsb", o.offset_lsb},
                                       {"--neighbour-rings", o.neighbour_rings}, {"--coordinate-bits", o.coordinate_bits}})
      if (given(cmd, option)) check_design_axis(option, text);
    resolve_design_options(o);
  } catch (const std::invalid_argument& e) {
    throw CLI::ValidationError(e.what());
  }
}

int run_design(const DesignCli& cli) {
  const DesignOptions& o = cli.options;
  Outputs outputs;
  const std::string dir = cli.out_dir;
  outputs.own_folder(dir, "design");
  for (const char* f : {"/design.json", "/design.csv", "/design.md", "/roofline.csv", "/best-device.json"})
    outputs.expect(dir + f);
  ProgressLine progress(!cli.quiet);
  const DesignSearchResult r = search_designs(o.workload, o.visibility, o.space, o.constraints, o.exhaustive,
                                              [&](const std::string& what) { progress.update("%-60s", what.c_str()); });
  progress.finish();
  const double paper_rate = measured_peak_software_rate(default_paper_table());
  const Roofline roofline = design_roofline(r, paper_rate);
  const DesignDocument doc{r, o.space, o.constraints, roofline, dir, cli.command};
  PlotProcess plotter("design.py");
  outputs.add(dir + "/design.json", pretty_json(design_json(doc)));
  outputs.add(dir + "/design.csv", design_csv(r));
  outputs.add(dir + "/roofline.csv", roofline_csv({roofline}));
  outputs.add(dir + "/design.md", design_markdown(doc));
  if (r.best) outputs.add(dir + "/best-device.json", pretty_json(profiles::json_of(r.points[*r.best].profile.document)));
  outputs.write();
  plotter.draw(dir + "/design.csv", dir + "/design.png");
  plotter.draw(dir + "/roofline.csv", dir + "/roofline.png");
  const bool drawn = plotter.finish();
  print_design(doc);
  std::printf("  wrote %s%s (%.1f s)\n", listed(outputs.paths()).c_str(),
              drawn ? (" and " + dir + "/design.png, roofline.png").c_str() : "", progress.seconds());
  return 0;
}

}  // namespace

void add_design_command(CLI::App& app, int& exit_code) {
  auto cli = std::make_shared<DesignCli>();
  DesignOptions* o = &cli->options;
  CLI::App* cmd = app.add_subcommand(
      "design", "Search one device's designs for a workload: the fastest feasible one and the Pareto front of time, "
                "energy, banks and error, every figure simulated (docs/design.md)");
  add_scene_options(*cmd, o->workload.scene);
  cmd->add_option("--steps", cli->steps,
                  "Steps every design replays (default: Table 2's for a paper scene, else to convergence; at most " +
                      std::to_string(SolverOptions{}.max_steps) + ")");
  cmd->add_flag("--culled", o->culled, "Cull receivers behind the shooter instead of sending every segment (the paper)");
  add_form_factor_option(*cmd, o->workload.form_factor);
  cmd->add_option("--device", o->space.device, "Device profile, configs/devices/NAME.json or a path")->capture_default_str();
  cmd->add_option("--host", o->space.host, "Host CPU profile")->capture_default_str();
  cmd->add_option("--lanes", o->lanes, "Lane counts, e.g. 1-8 (default: 1 .. the most that fit)");
  cmd->add_option("--banks", o->banks, "Bank counts, e.g. 5-14 (default: 5 .. --max-banks)");
  cmd->add_option("--bank-clocks", o->bank_clocks, "Bank clocks in MHz, e.g. 100,133 (default: the profile's)");
  cmd->add_option("--results", o->results, "Where results accumulate: bank, on_chip")->capture_default_str();
  cmd->add_option("--bits", o->bits, "Fractional widths, e.g. 15,23")->capture_default_str();
  cmd->add_option("--multipliers", o->multipliers, "block (block multipliers while they last), slice")
      ->capture_default_str();
  add_resources_option(*cmd, o->space.resources);
  cmd->add_option("--ray-split", cli->ray_split,
                  "How each pass divides its rays over the ray groups: limit (by what limits each group's stream, "
                  "result bank included) or nominal (the paper's lane rates); docs/board.md, Ray split")
      ->check(CLI::IsMember({"limit", "nominal"}))
      ->capture_default_str();
  cmd->add_option("--cards", o->cards, "Card counts, e.g. 1-4")->capture_default_str();
  cmd->add_option("--concurrent", o->concurrent, "Driver: on (sec 4.3), off, both")->capture_default_str();
  cmd->add_option("--offset-lsb", o->offset_lsb,
                  "Segment-end offsets along the normal in LSBs, e.g. 0,2 (0: off; run's --offset-lsb, docs/radiosity.md)")
      ->capture_default_str();
  cmd->add_option("--neighbour-rings", o->neighbour_rings, "Neighbour rules, e.g. 0-2 (0: off; run's --neighbour-rings)")
      ->capture_default_str();
  cmd->add_option("--coordinate-bits", o->coordinate_bits,
                  "Coordinate widths below the lanes' --bits, e.g. 0,15 (0: off; run's --coordinate-bits)")
      ->capture_default_str();
  cmd->add_option("--max-banks", o->constraints.max_banks, "Most banks a design may have (default: the profile's count; " + std::to_string(board::kMinBanks) + ".." +
                      std::to_string(kMaxRunBanks) + ")");
  cmd->add_option("--min-bits", o->constraints.min_bits, "Least fractional width a design may have (7..31)")
      ->capture_default_str();
  cmd->add_option("--max-energy", o->constraints.max_energy_joules, "Most energy a design's run may take, joules");
  cmd->add_option("--max-power", o->constraints.max_watts, "Most average power a design's run may draw, watts");
  cmd->add_option("--max-error", o->constraints.max_error,
                  "Largest error of the picture a design may have: relative RMSE of patch radiosity against double-precision "
                  "visibility on the workload (as `accuracy` measures it), e.g. 0.01");
  cmd->add_option("--max-error-max", o->constraints.max_error_max,
                  "Largest relative max error of patch radiosity a design may have (as `accuracy` measures it)");
  cmd->add_option("--fidelity", o->fidelity,
                  "on: measure each width's picture against one double-precision solve of the workload (its error, "
                  "an objective of the front); off: skip that solve (every design's error not measured)")
      ->capture_default_str();
  cmd->add_flag("--exhaustive", o->exhaustive, "Simulate every feasible design (no pruning of spare banks)");
  cmd->add_option("--out", cli->out_dir, "Output folder")->check(output_path())->capture_default_str();
  cmd->add_flag("--quiet", cli->quiet, "No progress output");
  add_jobs_option(*cmd, "the timing study's processes and the fast backend's threads");
  // The checks of --steps, --max-banks, --min-bits and the caps live in design_options.h (shared with
  // rc2000tlm.design()); check_and_resolve runs them on what was given.
  cmd->callback([cli, cmd, &exit_code] {
    cli->command = given_command(*cmd);
    check_and_resolve(*cmd, *cli);
    exit_code = run_guarded("design", cli->out_dir + "/", [&] { return run_design(*cli); });
  });
}

}  // namespace rc
