// `rc2000sim sweep` (issues #5 and #13): design-space studies. A study (study.h) comes from a study
// file (--study FILE, TOML, docs/studies.md) or from the command line's axes (--lanes, --banks,
// --bits, --devices, --concurrent, --host), which stay as shorthands. Every combination is a row;
// combinations that cannot exist get the reason and are not simulated. Each scene and width is
// solved once and every configuration replays it (sweep_study.h).
//
//   rc2000sim sweep [--study FILE | axes...] [--out DIR]      the whole study on this machine
//   rc2000sim sweep --study FILE --shard I/N --out DIR         one shard: DIR/shard-I-of-N.json
//   rc2000sim sweep merge DIR... --out DIR                     the shards, as one machine writes them
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <regex>
#include <sstream>

#include "apps/cli_options.h"
#include "apps/outputs.h"
#include "apps/plot.h"
#include "apps/progress.h"
#include "apps/report.h"
#include "board/profile_reader.h"
#include "host_sw/studies/study_file.h"
#include "host_sw/studies/study_table.h"
#include "host_sw/studies/sweep_study.h"
#include "host_sw/visibility/visibility_factory.h"

namespace rc {

namespace {

// 1,2,3,5 -> "1-3,5".
template <class Int>
std::string ranges(const std::vector<Int>& values) {
  std::string text;
  for (std::size_t i = 0; i < values.size();) {
    std::size_t j = i;
    while (j + 1 < values.size() && values[j + 1] == values[j] + 1) ++j;
    text += (text.empty() ? "" : ",") + std::to_string(values[i]) + (j > i ? "-" + std::to_string(values[j]) : "");
    i = j + 1;
  }
  return text;
}

std::string names(const std::vector<std::string>& items) {
  std::string text;
  for (const std::string& s : items) text += (text.empty() ? "" : ",") + s;
  return text;
}

// The command line's study, its defaults those of a study file (default_study()).
struct SweepOptions {
  SweepOptions() {
    const Study d = default_study_settings();  // no file read before --configs is known
    scene = d.scenes.front().options;
    lanes = ranges(d.axes.lanes);
    banks = ranges(d.axes.banks);
    bits = ranges(d.axes.bits);
    devices = names(d.axes.devices);
    hosts = names(d.axes.hosts);
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
  bool quiet = false;
  bool list_fields = false;
  std::string out_dir = "out/sweep";
};

struct MergeOptions {
  std::vector<std::string> inputs;
  std::string out_dir = "out/sweep";
  bool quiet = false;
};

// The options a study file replaces: each is an error beside --study.
const char* const kStudyOptions[] = {"--scene", "--faces", "--face-levels", "--patch-levels", "--patch-size",
                                     "--steps", "--convergence", "--lanes", "--banks", "--bits", "--devices",
                                     "--concurrent", "--paper-faithful", "--host", "--visibility", "--full-banks",
                                     "--cards", "--card-split", "--card-bus", "--form-factor"};

Study study_from_options(const SweepOptions& o) {
  Study s = default_study();
  s.name = "command-line";
  s.scenes = {{default_scene_name(o.scene), o.scene, o.scene.file, ""}};
  s.steps = parse_steps(o.steps);
  s.convergence = o.convergence;
  s.paper_faithful = o.paper_faithful;
  s.visibility = o.visibility;
  s.form_factor = o.form_factor;
  s.full_banks = o.full_banks;
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

// ---- the summary ----------------------------------------------------------------------------------

std::string cell(const SweepRow& r) {
  char text[16];
  if (r.validity == Validity::does_not_fit) return "fit";
  if (r.validity == Validity::too_few_banks) return "banks";
  if (r.validity != Validity::ok) return "-";
  std::snprintf(text, sizeof text, "%.3f", r.simulated_seconds);
  return text;
}

bool same_block(const SweepConfig& a, const SweepConfig& b) {
  if (a.device != b.device || a.bits != b.bits || a.concurrent != b.concurrent || a.host != b.host ||
      a.cards != b.cards || a.card_split != b.card_split || a.card_bus != b.card_bus)
    return false;
  for (std::size_t i = 0; i < a.settings.size(); ++i)
    if (a.settings[i].value != b.settings[i].value) return false;
  return true;
}

std::string block_title(const SweepConfig& c, bool show_host) {
  std::string title = c.device + ", " + std::to_string(c.bits) + "-bit, " + (c.concurrent ? "concurrent" : "serial") +
                      " driver";
  if (show_host) title += ", host " + c.host;
  if (c.cards > 1) title += ", " + std::to_string(c.cards) + " cards (" + choice_name(c.card_split) + ", " + choice_name(c.card_bus) + " bus)";
  for (const ProfileSetting& s : c.settings) title += ", " + s.text();
  return title;
}

// One lanes x banks block of simulated seconds per device, width, driver, host and profile values
// (rows are enumerated in that order, lanes and banks last: each block is contiguous).
void print_blocks(const std::vector<SweepRow>& rows, const SweepAxes& axes) {
  const std::size_t block = axes.banks.size();
  for (std::size_t first = 0; first < rows.size();) {
    const SweepConfig& c = rows[first].config;
    std::printf("\n%s: simulated seconds (fit: lanes do not fit; banks: too few banks)\n",
                block_title(c, axes.hosts.size() > 1).c_str());
    std::printf("  lanes \\ banks");
    for (int b : axes.banks) std::printf(" %8d", b);
    std::printf("\n");
    const SweepRow* best = nullptr;
    const SweepRow* frugal = nullptr;  // the least energy, among rows that have it
    std::size_t end = first;
    while (end < rows.size() && same_block(rows[end].config, c)) ++end;
    std::vector<unsigned> unfit;  // lane counts whose whole line does not fit the device
    for (std::size_t r = first; r < end; r += block) {
      if (rows[r].validity == Validity::does_not_fit) {
        unfit.push_back(rows[r].config.lanes);
        continue;
      }
      std::printf("  %13u", rows[r].config.lanes);
      for (std::size_t j = 0; j < block; ++j) {
        const SweepRow& x = rows[r + j];
        std::printf(" %8s", cell(x).c_str());
        if (x.validity == Validity::ok && (!best || x.simulated_seconds < best->simulated_seconds)) best = &x;
        if (x.validity == Validity::ok && std::isfinite(x.energy_joules) &&
            (!frugal || x.energy_joules < frugal->energy_joules))
          frugal = &x;
      }
      std::printf("\n");
    }
    if (!unfit.empty()) std::printf("  lanes %s: do not fit the device\n", ranges(unfit).c_str());
    if (best) {
      std::printf("  fastest: %u lanes, %u banks: %.3f s, %.2fx one lane, %.2fx software; bottleneck %s\n",
                  best->config.lanes, best->config.banks, best->simulated_seconds, best->speedup_vs_one_lane,
                  best->speedup_vs_software, best->bottleneck.c_str());
    }
    if (frugal) {
      std::printf("  most frugal: %u lanes, %u banks: %.4g J (%.4g J per step, %.4g W), %.3f s\n", frugal->config.lanes,
                  frugal->config.banks, frugal->energy_joules, frugal->energy_per_step_joules, frugal->average_watts,
                  frugal->simulated_seconds);
    } else if (best && !best->energy_missing.empty()) {
      std::printf("  energy: not estimated: %s\n", best->energy_missing.c_str());
    }
    first = end;
  }
}

// ---- sec 5.6 --------------------------------------------------------------------------------------

// Sec 5.6's "lanes that fit" for every device and width swept, each rule, on the profiles with the
// study's fixed settings and the first host.
struct SweptFit {
  int bits = 0;
  LanesThatFit estimates;
};

std::vector<SweptFit> swept_fits(const Study& s) {
  const std::string study = s.name;  // as run_study_shard names it
  const HostProfile host = with_settings(find_host_profile(s.axes.hosts.front()), s.fixed, study);
  std::vector<SweptFit> fits;
  for (const std::string& device : s.axes.devices) {
    const board::DeviceProfile d = with_settings(board::find_device_profile(device), s.fixed, study);
    for (int bits : s.axes.bits) fits.push_back({bits, lanes_that_fit(d, host, bits)});
  }
  return fits;
}

bool sweeps_device_fields(const Study& s) {
  return std::any_of(s.axes.profile.begin(), s.axes.profile.end(),
                     [](const ProfileAxis& a) { return a.field.kind == ProfileKind::device; });
}

// ---- sweep.json -----------------------------------------------------------------------------------

// The software-only seconds of one width: a number when the width has one software time (one host),
// else an object by software key.
nlohmann::ordered_json software_at(const SceneSweep& r, int bits) {
  const std::string prefix = std::to_string(bits) + "-bit ";
  nlohmann::ordered_json by_key = nlohmann::ordered_json::object();
  for (const auto& [key, seconds] : r.software_seconds)
    if (key.rfind(prefix, 0) == 0) by_key[key] = seconds;
  return by_key.size() == 1 ? by_key.begin().value() : by_key;
}

nlohmann::ordered_json sweep_json(const Study& s, const SceneSweep& r, const std::vector<SweptFit>& fits) {
  nlohmann::ordered_json j;
  j["schema"] = "rc2000sim.sweep/1";
  j["scene"] = {{"name", r.scene.name}, {"source", r.scene.source}, {"faces", r.scene.faces}, {"patches", r.scene.patches}};
  j["solver"] = {{"paper_faithful", s.paper_faithful}, {"steps_policy", to_string(s.steps)}, {"convergence", s.convergence},
                 {"visibility", s.visibility}};
  if (s.form_factor != Study{}.form_factor) j["solver"]["form_factor"] = s.form_factor;  // point: as before it existed
  j["host_profile"] = s.axes.hosts.size() == 1 ? nlohmann::ordered_json(s.axes.hosts.front())
                                               : nlohmann::ordered_json(s.axes.hosts);
  nlohmann::ordered_json w = nlohmann::ordered_json::array();
  for (const auto& [bits, width] : r.widths) {
    w.push_back({{"bits", bits},
                 {"steps", width.steps},
                 {"convergence_step", width.convergence_step > 0  // null: not within the replayed steps
                                          ? nlohmann::ordered_json(width.convergence_step)
                                          : nlohmann::ordered_json()},
                 {"max_segments_per_step", width.max_segments},
                 {"software_seconds", software_at(r, bits)}});
  }
  j["widths"] = w;
  nlohmann::ordered_json banks;
  for (const auto& [device, bytes] : r.bank_capacities) banks[device] = bytes;
  j["modelled_bank_capacity_bytes"] = banks;
  j["bank_capacity_note"] =
      "0: the profile's banks. Otherwise banks of this size, which change no pass, transfer or time for this "
      "scene (no step batches with either size; studies/config_sweep.cpp), to keep the model's memory small";
  nlohmann::ordered_json estimates = nlohmann::ordered_json::array();
  for (const SweptFit& f : fits) {
    nlohmann::ordered_json e = {{"device", f.estimates.model.device}, {"bits", f.bits}};
    e.update(lanes_that_fit_json(f.estimates));
    estimates.push_back(e);
  }
  j["lanes_that_fit"] = estimates;
  if (sweeps_device_fields(s)) {
    j["lanes_that_fit_note"] = "on the device profiles with the study's fixed settings; the device fields swept as "
                               "axes change each row's own clock_mhz and layout, not these estimates";
  }
  const std::vector<std::string> extra = extra_columns(s.axes);
  nlohmann::ordered_json records = nlohmann::ordered_json::array();
  for (const SweepRow& row : r.rows) records.push_back(sweep_row_json(row, extra));
  j["rows"] = records;
  return j;
}

// One line per key and per row: the file stays as diff-able as the CSV and a third of dump(2)'s size.
std::string json_text(const nlohmann::ordered_json& j) {
  std::ostringstream out;
  out << "{\n";
  for (auto it = j.begin(); it != j.end(); ++it) {
    out << "  " << nlohmann::json(it.key()).dump() << ": ";
    if (it.key() != "rows") {
      out << it.value().dump() << (std::next(it) != j.end() ? ",\n" : "\n");
      continue;
    }
    out << "[\n";
    for (std::size_t i = 0; i < it.value().size(); ++i)
      out << "    " << it.value()[i].dump() << (i + 1 < it.value().size() ? ",\n" : "\n");
    out << "  ]" << (std::next(it) != j.end() ? ",\n" : "\n");
  }
  out << "}\n";
  return out.str();
}

// ---- writing a study ------------------------------------------------------------------------------

// The study as run and the tool that ran it, in every output folder.
std::string study_record(const StudyResult& r) {
  nlohmann::ordered_json j;
  j["tool"] = r.tool;
  j["study"] = study_json(r.study);
  return j.dump(2) + "\n";
}

void print_scene(const Study& s, const SceneSweep& r, const std::vector<SweptFit>& fits) {
  std::printf("rc2000sim sweep: %s, %llu faces, %llu patches, %s, host %s\n", r.scene.name.c_str(),
              static_cast<unsigned long long>(r.scene.faces), static_cast<unsigned long long>(r.scene.patches),
              s.paper_faithful ? "paper-faithful (every segment)" : "receivers culled", names(s.axes.hosts).c_str());
  for (const auto& [bits, w] : r.widths) {
    const nlohmann::ordered_json software = software_at(r, bits);
    if (software.is_number()) {
      std::printf("  %d-bit: %d steps replayed; software alone %.3f s\n", bits, w.steps, software.get<double>());
    } else {
      std::printf("  %d-bit: %d steps replayed; software alone:", bits, w.steps);
      for (auto it = software.begin(); it != software.end(); ++it)
        std::printf(" %s %.3f s;", it.key().c_str(), it.value().get<double>());
      std::printf("\n");
    }
  }
  std::printf("  %zu configurations: %zu simulated, %zu cannot exist\n", r.rows.size(), r.valid, r.rows.size() - r.valid);
  print_blocks(r.rows, s.axes);
  std::printf("\n  sec 5.6, lanes that fit at full rate (docs/calibration.md):\n");
  for (const SweptFit& f : fits) std::printf("    %d-bit %s\n", f.bits, lanes_that_fit_line(f.estimates).c_str());
}

// The folder of each scene's files: `out` itself for a one-scene study, else a folder per scene.
std::string scene_dir(const Study& s, std::size_t i, const std::string& out) {
  return s.scenes.size() == 1 ? out : out + "/" + s.scenes[i].name;
}

// Before any work: every file the study will write can be written.
void expect_study_outputs(const Study& s, const std::string& out) {
  Outputs outputs;
  outputs.expect(out + "/study.json");
  for (std::size_t i = 0; i < s.scenes.size(); ++i) outputs.expect(scene_dir(s, i, out) + "/sweep.csv");
  if (s.scenes.size() > 1) outputs.expect(out + "/study.csv");
}

// Each scene's sweep.csv and sweep.json, and study.json beside them (written last: its presence
// means a complete study); then the summaries and the plots.
void write_study(const StudyResult& r, const std::string& out, const ProgressLine& clock) {
  const std::vector<SweptFit> fits = swept_fits(r.study);
  const std::vector<std::string> extra = extra_columns(r.study.axes);
  Outputs outputs;
  for (std::size_t i = 0; i < r.scenes.size(); ++i) {
    const std::string dir = scene_dir(r.study, i, out);
    std::ostringstream csv;
    write_sweep_csv(csv, r.scenes[i].rows, extra);
    outputs.add(dir + "/sweep.csv", csv.str());
    outputs.add(dir + "/sweep.json", json_text(sweep_json(r.study, r.scenes[i], fits)));
  }
  if (r.scenes.size() > 1) {  // every scene's rows in one table with a scene column (study_table.h)
    std::ostringstream table;
    write_study_table_csv(table, r, extra);
    outputs.add(out + "/study.csv", table.str());
  }
  outputs.add(out + "/study.json", study_record(r));
  outputs.write();
  for (std::size_t i = 0; i < r.scenes.size(); ++i) {
    const std::string dir = scene_dir(r.study, i, out);
    if (i > 0) std::printf("\n");
    print_scene(r.study, r.scenes[i], fits);
    const bool drawn = plot("sweep.py", dir + "/sweep.csv", dir);
    std::printf("\n  wrote %s/sweep.csv, sweep.json%s\n", dir.c_str(), drawn ? " and plots" : "");
  }
  std::printf("  wrote %s/study.json (%.1f s in all)\n", out.c_str(), clock.seconds());
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

// ---- --list-fields --------------------------------------------------------------------------------

void list_fields(const std::string& title, const std::string& prefix, const nlohmann::ordered_json& profile) {
  std::printf("%s\n", title.c_str());
  for (const std::string& f : sourced_fields(profile)) {
    const nlohmann::ordered_json* node = &profile;
    for (std::size_t from = 0, dot = 0; dot != std::string::npos; from = dot + 1) {
      dot = f.find('.', from);
      node = &(*node)[f.substr(from, dot == std::string::npos ? std::string::npos : dot - from)];
    }
    std::printf("  %-48s %s\n", (prefix + f).c_str(), (*node)["value"].dump().c_str());
  }
}

// Every field a study can sweep or fix, with its value in each profile (a path's home in one step).
int run_list_fields(const Study& s) {
  for (const std::string& d : s.axes.devices) {
    const board::DeviceProfile p = board::find_device_profile(d);
    list_fields("device profile " + p.file + " (paths as written in [axes] or [fixed]):", "", p.json);
  }
  for (const std::string& h : s.axes.hosts) {
    const HostProfile p = find_host_profile(h);
    list_fields("host profile " + p.file + ":", "host.", p.json);
  }
  std::printf("A leaf name that is unique within its profile may stand for its path (host.segment_pack).\n");
  return 0;
}

// ---- merge ----------------------------------------------------------------------------------------

// A shard holds a study's recorded steps: far more than a profile, far less than this.
constexpr std::uint64_t kShardLimitBytes = 1ull << 30;

bool is_shard_file(const std::filesystem::path& p) {
  static const std::regex name(R"(shard-[0-9]+-of-[0-9]+\.json)");
  return std::regex_match(p.filename().string(), name);
}

// The shard files named, or found in the folders named (in name order, so errors are stable).
std::vector<std::string> shard_files(const std::vector<std::string>& inputs) {
  std::vector<std::string> files;
  for (const std::string& input : inputs) {
    if (std::filesystem::is_directory(input)) {
      std::vector<std::string> found;
      for (const auto& entry : std::filesystem::directory_iterator(input))
        if (entry.is_regular_file() && is_shard_file(entry.path())) found.push_back(entry.path().string());
      if (found.empty()) throw std::invalid_argument(input + ": no shard files (shard-I-of-N.json) in this folder");
      std::sort(found.begin(), found.end());
      files.insert(files.end(), found.begin(), found.end());
    } else if (std::filesystem::is_regular_file(input)) {
      files.push_back(input);
    } else {
      std::error_code absent;
      throw std::invalid_argument(input + (std::filesystem::exists(input, absent)
                                               ? ": not a shard file or a folder of them (a device or a pipe)"
                                               : ": no such shard file or folder"));
    }
  }
  return files;
}

int run_merge(const MergeOptions& o) {
  ProgressLine progress(!o.quiet);
  const std::vector<std::string> files = shard_files(o.inputs);
  std::vector<ShardResult> shards;
  for (const std::string& f : files)
    shards.push_back(shard_from_json(board::read_json_file(f, kShardLimitBytes, "a shard file"), f));
  const StudyResult result = merge_shards(shards, files);
  expect_study_outputs(result.study, o.out_dir);
  std::printf("rc2000sim sweep merge: study %s, %zu shard(s)\n", result.study.name.c_str(), shards.size());
  write_study(result, o.out_dir, progress);
  return 0;
}

void add_merge_command(CLI::App& sweep, int& exit_code) {
  auto o = std::make_shared<MergeOptions>();
  CLI::App* cmd = sweep.add_subcommand(
      "merge", "Put the shards of a study together (shard files, or folders holding them): the same outputs as one "
               "machine writes");
  cmd->add_option("inputs", o->inputs, "Shard files (shard-I-of-N.json) or folders holding them")->required();
  cmd->add_option("--out", o->out_dir, "Output folder for sweep.csv, sweep.json, study.json and the plots")
      ->check(output_path())
      ->capture_default_str();
  cmd->add_flag("--quiet", o->quiet, "No progress output");
  cmd->callback([o, &sweep, &exit_code] {
    // `sweep --lanes 3 merge ...`: the sweep's own options would be ignored; the shards carry the study.
    for (const CLI::Option* option : sweep.get_options()) {
      if (option->count() > 0 && option->get_name() != "--help") {
        refuse_option(option->get_name(), "does not apply to sweep merge: the shards carry their study (merge takes "
                                           "its own --out and --quiet, after 'merge')");
      }
    }
    exit_code = run_guarded("sweep merge", o->out_dir + "/", [&] { return run_merge(*o); });
  });
}

}  // namespace

void add_sweep_command(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<SweepOptions>();
  CLI::App* cmd = app.add_subcommand(
      "sweep", "Design-space study: lanes x banks x width x device x driver x host x any profile field, for one or "
               "more scenes (default: the paper's 280 faces, 1120 patches), one CSV row per configuration");
  cmd->add_option("--study", o->study_file, "Study file (TOML, docs/studies.md); replaces the scene, solver and axis options");
  cmd->add_option("--shard", o->shard, "Run shard I of N (I/N, from 0) of the study: writes OUT/shard-I-of-N.json for "
                                       "`sweep merge`");
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
  cmd->add_option("--out", o->out_dir, "Output folder for sweep.csv, sweep.json, study.json and the plots (with "
                                       "--shard: for the shard file)")->check(output_path())
      ->capture_default_str();
  cmd->add_flag("--full-banks", o->full_banks,
                "Model the profile's bank capacity even when smaller banks change nothing (more memory)");
  cmd->add_flag("--quiet", o->quiet, "No progress output");
  cmd->add_flag("--list-fields", o->list_fields,
                "List the profile fields a study can sweep or fix, with their values, for --devices and --host (or "
                "the study's), and exit");
  add_merge_command(*cmd, exit_code);
  cmd->require_subcommand(0, 1);
  cmd->callback([o, cmd, &exit_code] {
    if (cmd->got_subcommand("merge")) return;  // merge ran its own callback
    // Empty, they would mean "no study" and "no shard": the whole default sweep, silently.
    if (given(*cmd, "--study") && o->study_file.empty()) refuse_option("--study", "is empty: name a study file (docs/studies.md)");
    if (given(*cmd, "--shard") && o->shard.empty()) refuse_option("--shard", "is empty: expected I/N (shard I of N, counted from 0)");
    if (o->list_fields)
      refuse_given(*cmd, {"--out", "--shard"}, "does not apply with --list-fields (it lists the fields and writes nothing)");
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
    // A scene file is taken as it is unless refinement is asked for: the paper defaults are for
    // the embedded box.
    if (!o->scene.file.empty()) {
      const SceneOptions plain;
      if (cmd->count("--faces") == 0) o->scene.face_target = plain.face_target;
      if (cmd->count("--face-levels") == 0) o->scene.face_levels = plain.face_levels;
      if (cmd->count("--patch-levels") == 0) o->scene.patch_levels = plain.patch_levels;
    }
    exit_code = run(study_from_options(*o));
  });
}

}  // namespace rc
