// `rc2000sim sweep` (issues #5 and #13): design-space studies. A study (study.h) comes from a study
// file (--study FILE, TOML, docs/studies.md) or from the command line's axes (--lanes, --banks,
// --bits, --devices, --concurrent, --host), which stay as shorthands. Every combination is a row;
// combinations that cannot exist get the reason and are not simulated. Each scene and width is
// solved once and every configuration replays it (sweep_study.h).
//
//   rc2000sim sweep [--study FILE | axes...] [--out DIR]      the whole study on this machine
//   rc2000sim sweep --study FILE --shard I/N --out DIR         one shard: DIR/shard-I-of-N.json
//   rc2000sim sweep merge DIR... --out DIR                     the shards, as one machine writes them
#include <cstdio>
#include <memory>

#include "apps/cli_options.h"
#include "apps/outputs.h"
#include "apps/progress.h"
#include "apps/sweep_fields.h"
#include "apps/sweep_merge.h"
#include "apps/sweep_summary.h"
#include "apps/sweep_writer.h"
#include "host_sw/studies/workload.h"
#include "host_sw/studies/shard_json.h"
#include "host_sw/studies/study_file.h"
#include "host_sw/visibility/visibility_factory.h"

namespace rc {

namespace {

// The command line's study, its defaults those of a study file (default_study()).
struct SweepOptions {
  SweepOptions() {
    const Study d = default_study_settings();  // no file read before --configs is known
    scene = d.scenes.front().options;
    lanes = range_list_text(d.axes.lanes);
    banks = range_list_text(d.axes.banks);
    bits = range_list_text(d.axes.bits);
    devices = name_list_text(d.axes.devices);
    hosts = name_list_text(d.axes.hosts);
    steps = to_string(d.steps);
    convergence = d.convergence;
  }
  std::string study_file, shard;
  SceneOptions scene;
  std::string steps;
  double convergence = 0;
  std::string lanes, banks, bits, devices, hosts;
  std::string cards = "1", card_split = "rays", card_bus = "shared";
  std::string concurrent = "on";
  bool paper_faithful = true;
  std::string visibility = "fast";
  std::string form_factor = Study{}.form_factor;  // the paper's point rule (a sweep replicates its workload)
  bool full_banks = false;
  pipeline::ResourceSource resources = pipeline::ResourceSource::paper_fit;
  std::string ray_split = "limit";
  bool quiet = false;
  bool list_fields = false;
  std::string out_dir = "out/sweep";
};

// The options a study file replaces: each is an error beside --study.
const char* const kStudyOptions[] = {"--scene", "--faces", "--face-levels", "--patch-levels", "--patch-size",
                                     "--steps", "--convergence", "--lanes", "--banks", "--bits", "--devices",
                                     "--concurrent", "--paper-faithful", "--host", "--visibility", "--full-banks",
                                     "--cards", "--card-split", "--card-bus", "--form-factor", "--resources",
                                     "--ray-split"};

Study study_from_options(const SweepOptions& o) {
  Study s = default_study();
  s.name = "command-line";
  s.scenes = {{default_scene_name(o.scene), o.scene, o.scene.file, ""}};
  s.steps = parse_steps(o.steps);
  s.convergence = o.convergence;
  s.paper_faithful = o.paper_faithful;
  s.visibility = parse_choice<BitExactVisibility>(o.visibility);  // CLI::IsMember has checked the name
  s.form_factor = o.form_factor;
  s.full_banks = o.full_banks;
  s.resources = o.resources;
  s.ray_split = board::parse_ray_split(o.ray_split);
  s.axes.devices = parse_name_list(o.devices, "--devices");
  s.axes.hosts = parse_name_list(o.hosts, "--host");
  s.axes.bits = parse_int_list(o.bits, "--bits", 7, 31);
  s.axes.concurrent = parse_concurrency(o.concurrent);
  s.axes.lanes = parse_int_list(o.lanes, "--lanes", board::LaneCount::kMin, board::LaneCount::kMax);
  s.axes.banks = parse_int_list(o.banks, "--banks", 1, 255);
  s.axes.cards = parse_int_list(o.cards, "--cards", CardCount::kMin, CardCount::kMax);
  s.axes.card_splits = parse_choice_list<CardSplit>(o.card_split, "--card-split");
  s.axes.card_buses = parse_choice_list<CardBus>(o.card_bus, "--card-bus");
  check_study(s);
  return s;
}

std::string shard_path(const std::string& dir, const Shard& s) {
  return dir + "/shard-" + std::to_string(s.index) + "-of-" + std::to_string(s.count) + ".json";
}

int run_sweep(const SweepOptions& o, const Study& study) {
  ProgressLine progress(!o.quiet);
  auto report = [&](const std::string& what) { progress.update("%-70s", what.c_str()); };
  if (!o.shard.empty()) {
    const Shard shard = parse_shard(o.shard);
    const std::string path = shard_path(o.out_dir, shard);
    Outputs outputs;
    outputs.own_folder(o.out_dir, "sweep --shard", shard_listing_set(study, shard.count));
    outputs.expect(path);
    const ShardResult result = run_study_shard(study, shard, report);
    progress.finish();
    outputs.add(path, shard_json(result).dump() + "\n");
    outputs.write();
    std::printf("rc2000sim sweep: study %s, shard %s: %zu of %zu solve(s) (scene x width); wrote %s (%.1f s)\n",
                study.name.c_str(), shard.text().c_str(), result.groups.size(), result.groups_in_study, path.c_str(),
                progress.seconds());
    if (result.groups.empty())
      std::printf("  this shard has no solve: the study has %zu, fewer than %u shards\n", result.groups_in_study, shard.count);
    return 0;
  }
  expect_study_outputs(study, o.out_dir);
  const StudyResult result = run_study(study, report);
  progress.finish();
  write_study(result, o.out_dir, progress);
  return 0;
}

}  // namespace

std::function<Study()> add_sweep_study_options(CLI::App& command) {
  auto o = std::make_shared<SweepOptions>();  // its study fields; the command's own are add_sweep_command's
  CLI::App* cmd = &command;
  add_scene_options(*cmd, o->scene);
  cmd->add_option("--steps", o->steps,
                  "paper (Table 2's count for a paper scene, else converge), converge (steps to --convergence, per "
                  "width) or a step count")
      ->capture_default_str();
  cmd->add_option("--convergence", o->convergence, "Convergence target of --steps converge")
      ->check(convergence_target())->capture_default_str();
  cmd->add_option("--lanes", o->lanes, "Lane counts: list and ranges, e.g. 1-4,8")->capture_default_str();
  cmd->add_option("--banks", o->banks, "Bank counts: list and ranges")->capture_default_str();
  cmd->add_option("--bits", o->bits, "Fractional widths (7..31), list and ranges; each is solved once")
      ->capture_default_str();
  cmd->add_option("--devices", o->devices, "Device profiles (configs/devices/NAME.json or paths), comma-separated")
      ->capture_default_str();
  cmd->add_option("--concurrent", o->concurrent, "Driver: on (concurrent, sec 4.3), off (serial) or both")
      ->check(CLI::IsMember({"on", "off", "both"}))->capture_default_str();
  cmd->add_flag("--paper-faithful,!--cull-receivers", o->paper_faithful,
                "Segments to every other patch, as the paper (default); --cull-receivers: only to patches in front");
  cmd->add_option("--cards", o->cards, "Card counts (1..16), list and ranges; several cards: docs/board.md")
      ->capture_default_str();
  cmd->add_option("--card-split", o->card_split, "Several cards: rays and/or faces, comma-separated")->capture_default_str();
  cmd->add_option("--card-bus", o->card_bus, "Several cards: shared and/or separate, comma-separated")->capture_default_str();
  cmd->add_option("--host", o->hosts, "Host profiles (configs/hosts/NAME.json or paths), comma-separated")
      ->capture_default_str();
  cmd->add_option("--visibility", o->visibility, "Bit-exact backend that answers visibility once per width: fixed or fast")
      ->check(CLI::IsMember(choice_names<BitExactVisibility>()))->capture_default_str();
  add_form_factor_option(*cmd, o->form_factor, "Every solve (default: the paper's point rule): ");
  cmd->add_flag("--full-banks", o->full_banks,
                "Model the profile's bank capacity even when smaller banks change nothing (more memory)");
  add_resources_option(*cmd, o->resources);
  cmd->add_option("--ray-split", o->ray_split,
                  "How each pass divides its rays over the ray groups: limit (by what limits each group's stream, "
                  "result bank included) or nominal (the paper's lane rates); docs/board.md, Ray split")
      ->check(CLI::IsMember({"limit", "nominal"}))->capture_default_str();
  return [o, cmd] {
    // A scene file is taken as it is unless refinement is asked for, and solved with run's form
    // factor unless one is given: the paper defaults are for the embedded box (workload.h).
    take_scene_as_given(o->scene, [&](const std::string& option) { return cmd->count(option) > 0; });
    if (!o->scene.file.empty() && cmd->count("--form-factor") == 0) o->form_factor = to_string(kSceneFileFormFactor);
    return study_from_options(*o);
  };
}

void add_sweep_command(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<SweepOptions>();  // the command's own options: study file, shard, folder, terminal
  CLI::App* cmd = app.add_subcommand(
      "sweep", "Design-space study: lanes x banks x width x device x driver x host x any profile field, for one or "
               "more scenes (default: the paper's 280 faces, 1120 patches), one CSV row per configuration");
  cmd->add_option("--study", o->study_file, "Study file (TOML, docs/studies.md); replaces the scene, solver and axis options");
  cmd->add_option("--shard", o->shard, "Run shard I of N (I/N, from 0) of the study: writes OUT/shard-I-of-N.json for "
                                       "`sweep merge`");
  const std::function<Study()> study_of_options = add_sweep_study_options(*cmd);
  cmd->add_option("--out", o->out_dir, "Output folder for sweep.csv, sweep.json, study.json and the plots (with "
                                       "--shard: for the shard file)")->check(output_path())
      ->capture_default_str();
  cmd->add_flag("--quiet", o->quiet, "No progress output");
  add_jobs_option(*cmd, "the timing study's processes and the fast backend's threads");
  cmd->add_flag("--list-fields", o->list_fields,
                "List the profile fields a study can sweep or fix, with their values, for --devices and --host (or "
                "the study's), and exit");
  add_merge_command(*cmd, exit_code);
  cmd->require_subcommand(0, 1);
  cmd->callback([o, cmd, study_of_options, &exit_code] {
    if (cmd->got_subcommand("merge")) return;  // merge ran its own callback
    // Empty, they would mean "no study" and "no shard": the whole default sweep, silently.
    if (given(*cmd, "--study") && o->study_file.empty()) refuse_option("--study", "is empty: name a study file (docs/studies.md)");
    if (given(*cmd, "--shard") && o->shard.empty()) refuse_option("--shard", "is empty: expected I/N (shard I of N, counted from 0)");
    if (o->list_fields)
      refuse_given(*cmd, {"--out", "--shard", "--jobs"}, "does not apply with --list-fields (it lists the fields and writes nothing)");
    auto run = [&](const Study& study) {
      if (o->list_fields) return run_list_fields(study);
      return run_guarded("sweep", o->out_dir + "/", [&] { return run_sweep(*o, study); });
    };
    if (!o->study_file.empty()) {
      for (const char* option : kStudyOptions) {
        if (cmd->count(option) > 0) {
          refuse_option(option, "does not apply with --study: the study file " + o->study_file +
                                    " sets the scenes, solver and axes (edit it instead)");
        }
      }
      exit_code = run(load_study_file(o->study_file));
      return;
    }
    exit_code = run(study_of_options());
  });
}

}  // namespace rc
