// `rc2000sim design` (issue 25, docs/design.md): the fastest feasible design of one device for one
// workload, and the Pareto front of time, energy and banks, every figure simulated
// (host_sw/studies/design_search.h). Writes design.json, design.csv, design.md, roofline.csv,
// best-device.json (the best design's profile, for `rc2000sim run --device`) and two plots.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "apps/cli_options.h"
#include "apps/design_document.h"
#include "apps/outputs.h"
#include "apps/plot.h"
#include "apps/progress.h"
#include "apps/report.h"
#include "host_sw/profiles/profile_json.h"
#include "host_sw/studies/paper_workload.h"

namespace rc {

namespace {

struct DesignOptions {
  DesignWorkload workload;
  DesignSpace space;
  DesignConstraints constraints;
  std::string lanes, banks, bank_clocks, results = "bank,on_chip", bits = "15", multipliers = "block,slice";
  std::string cards = "1", concurrent = "on";
  std::string form_factor = "point";
  bool culled = false, exhaustive = false, quiet = false;
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

std::vector<double> parse_clocks(const std::string& text) {
  std::vector<double> clocks;
  for (const std::string& item : parse_name_list(text, "--bank-clocks")) {
    std::size_t used = 0;
    double mhz = 0;
    try {
      mhz = std::stod(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != item.size() || !std::isfinite(mhz) || mhz <= 0)
      throw CLI::ValidationError("--bank-clocks: '" + item + "' is not a clock in MHz above 0");
    clocks.push_back(mhz);
  }
  return clocks;
}

void resolve(DesignOptions& o) {
  DesignSpace& s = o.space;
  if (!o.lanes.empty()) s.lanes = parse_int_list(o.lanes, "--lanes", board::LaneCount::kMin, board::LaneCount::kMax);
  if (!o.banks.empty()) s.banks = parse_int_list(o.banks, "--banks", board::kMinBanks, kMaxRunBanks);
  if (!o.bank_clocks.empty()) s.bank_clocks_mhz = parse_clocks(o.bank_clocks);
  s.results.clear();
  for (const std::string& r : parse_name_list(o.results, "--results")) {
    if (r == "bank") s.results.push_back(board::ResultStore::bank);
    else if (r == "on_chip") s.results.push_back(board::ResultStore::on_chip);
    else throw CLI::ValidationError("--results: '" + r + "' is not one of bank, on_chip");
  }
  s.bits = parse_int_list(o.bits, "--bits", 7, 31);
  if (std::none_of(s.bits.begin(), s.bits.end(), [&](int b) { return b >= o.constraints.min_bits; }))
    throw CLI::ValidationError("--min-bits: " + std::to_string(o.constraints.min_bits) + " leaves no width of --bits " +
                               o.bits + " to search; give --bits with a width of at least " +
                               std::to_string(o.constraints.min_bits));
  s.multipliers.clear();
  for (const std::string& m : parse_name_list(o.multipliers, "--multipliers")) s.multipliers.push_back(parse_multipliers(m));
  s.cards = parse_int_list(o.cards, "--cards", CardCount::kMin, CardCount::kMax);
  s.concurrent = parse_concurrency(o.concurrent);
  o.workload.paper_faithful = !o.culled;
  o.workload.form_factor = o.form_factor;
  if (o.constraints.max_banks > kMaxRunBanks)
    throw CLI::ValidationError("--max-banks: " + std::to_string(o.constraints.max_banks) + " is above " +
                               std::to_string(kMaxRunBanks) + ", the most `rc2000sim run --banks` takes");
}

int run_design(const DesignOptions& o) {
  Outputs outputs;
  const std::string dir = o.out_dir;
  for (const char* f : {"/design.json", "/design.csv", "/design.md", "/roofline.csv", "/best-device.json"})
    outputs.expect(dir + f);
  ProgressLine progress(!o.quiet);
  const DesignSearchResult r = search_designs(o.workload, o.space, o.constraints, o.exhaustive,
                                              [&](const std::string& what) { progress.update("%-60s", what.c_str()); });
  progress.finish();
  const double paper_rate = measured_peak_software_rate(load_paper_table(default_paper_table_path()));
  const Roofline roofline = design_roofline(r, paper_rate);
  const DesignDocument doc{r, o.space, o.constraints, roofline, dir, o.command};
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
  auto o = std::make_shared<DesignOptions>();
  CLI::App* cmd = app.add_subcommand(
      "design", "Search one device's designs for a workload: the fastest feasible one and the Pareto front of time, "
                "energy and banks, every figure simulated (docs/design.md)");
  add_scene_options(*cmd, o->workload.scene);
  cmd->add_option("--steps", o->workload.steps,
                  "Steps every design replays (default: Table 2's for a paper scene, else to convergence)")
      ->check(CLI::Range(1, SolverOptions{}.max_steps));
  cmd->add_flag("--culled", o->culled, "Cull receivers behind the shooter instead of sending every segment (the paper)");
  add_form_factor_option(*cmd, o->form_factor);
  cmd->add_option("--device", o->space.device, "Device profile, configs/devices/NAME.json or a path")->capture_default_str();
  cmd->add_option("--host", o->space.host, "Host CPU profile")->capture_default_str();
  cmd->add_option("--lanes", o->lanes, "Lane counts, e.g. 1-8 (default: 1 .. the most that fit)");
  cmd->add_option("--banks", o->banks, "Bank counts, e.g. 5-14 (default: 5 .. --max-banks)");
  cmd->add_option("--bank-clocks", o->bank_clocks, "Bank clocks in MHz, e.g. 100,133 (default: the profile's)");
  cmd->add_option("--results", o->results, "Where results accumulate: bank, on_chip")->capture_default_str();
  cmd->add_option("--bits", o->bits, "Fractional widths, e.g. 15,23")->capture_default_str();
  cmd->add_option("--multipliers", o->multipliers, "block (block multipliers while they last), slice")
      ->capture_default_str();
  cmd->add_option("--cards", o->cards, "Card counts, e.g. 1-4")->capture_default_str();
  cmd->add_option("--concurrent", o->concurrent, "Driver: on (sec 4.3), off, both")->capture_default_str();
  cmd->add_option("--max-banks", o->constraints.max_banks, "Most banks a design may have (default: the profile's count)")
      ->check(CLI::Range(board::kMinBanks, 255u));
  cmd->add_option("--min-bits", o->constraints.min_bits, "Least fractional width a design may have")
      ->check(CLI::Range(7, 31))->capture_default_str();
  cmd->add_option("--max-energy", o->constraints.max_energy_joules, "Most energy a design's run may take, joules")
      ->check(positive_finite());
  cmd->add_option("--max-power", o->constraints.max_watts, "Most average power a design's run may draw, watts")
      ->check(positive_finite());
  cmd->add_flag("--exhaustive", o->exhaustive, "Simulate every feasible design (no pruning of spare banks)");
  cmd->add_option("--out", o->out_dir, "Output folder")->check(output_path())->capture_default_str();
  cmd->add_flag("--quiet", o->quiet, "No progress output");
  cmd->callback([o, cmd, &exit_code] {
    o->command = given_command(*cmd);
    resolve(*o);
    exit_code = run_guarded("design", o->out_dir + "/", [&] { return run_design(*o); });
  });
}

}  // namespace rc
