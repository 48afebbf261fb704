// `rc2000sim sweep` (issue #5, what-if studies): lanes, banks, width, device and driver for one
// scene, one CSV row per configuration. Configurations that cannot exist (lanes that do not fit
// the device, too few banks to feed them) are reported with the reason and not simulated. The scene
// is solved once per width (bit-exact visibility, recorded); every configuration that can exist
// replays that recording through its own SystemC system, all in one simulation (timing_study.h),
// beside one software-only system per width for the speedups. docs/results/sweep.md.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>

#include "apps/cli_options.h"
#include "studies/paper_workload.h"
#include "apps/plot.h"
#include "apps/progress.h"
#include "studies/config_sweep.h"

namespace rc {

namespace {

struct SweepOptions {
  SceneOptions scene = paper_scene_options(280, 1120);  // a Table 2 scene that sweeps in seconds
  std::string steps = "paper";
  double convergence = SolverOptions{}.convergence;
  std::string lanes = "1-16";
  std::string banks = "5-12";
  std::string bits = "15";
  std::string devices = "xc2v6000,virtex4-sx55,spartan3-5000";
  std::string concurrent = "on";
  bool paper_faithful = true;
  std::string host = "athlon-mp-2600-calibrated";
  std::string visibility = "fast";
  std::string out_dir = "out/sweep";
  bool full_banks = false;
  bool quiet = false;
};

// ---- the workload ---------------------------------------------------------------------------------

// One width's functional answer and the steps every configuration at that width replays.
struct WidthRun {
  RecordedRun functional;
  int steps = 0;
  std::uint64_t max_segments = 0;  // in one step, over the replayed steps
};

// Table 2's step count when the scene is one of the paper's (our Cornell Box refined to 70 faces,
// then split); 0 otherwise.
int paper_steps(const SweepOptions& o, const Scene& scene) {
  if (!o.scene.file.empty() || o.scene.face_target != 70) return 0;
  for (const PaperRow& row : load_paper_table(default_paper_table_path())) {
    if (static_cast<std::size_t>(row.faces) == scene.faces.size() &&
        static_cast<std::size_t>(row.patches) == scene.patches.size())
      return row.steps;
  }
  return 0;
}

SolverOptions base_solver(const SweepOptions& o) {
  SolverOptions s;
  s.cull_receivers = !o.paper_faithful;
  s.convergence = o.convergence;
  return s;
}

WidthRun record_width(const SweepOptions& o, const Scene& scene, int bits, int fixed_steps) {
  SolverOptions solver = base_solver(o);
  solver.fixed_steps = fixed_steps;  // 0: to convergence
  WidthRun w;
  w.functional = record_functional_run(scene, solver, o.visibility, bits);
  w.steps = w.functional.result.steps;
  for (int s = 0; s < w.steps; ++s)
    w.max_segments = std::max<std::uint64_t>(w.max_segments, w.functional.recording.segments(static_cast<std::size_t>(s)));
  return w;
}

// ---- the study ------------------------------------------------------------------------------------

struct Planned {
  SweepConfig config;
  ConfigCheck check;
  std::uint64_t bank_capacity = 0;  // 0: the profile's
  std::size_t outcome = 0;          // index into the study's outcomes (ok configurations)
};

TimingCase base_case(const Scene& scene, const SweepOptions& o, const WidthRun& w) {
  TimingCase c;
  c.scene = &scene;
  c.solver = base_solver(o);
  c.solver.fixed_steps = w.steps;
  c.recording = &w.functional.recording;
  return c;
}

TimingCase software_case(const Scene& scene, const SweepOptions& o, int bits, const WidthRun& w) {
  TimingCase c = base_case(scene, o, w);
  c.label = "software " + std::to_string(bits) + "-bit";
  c.software = true;
  c.host = o.host;
  return c;
}

TimingCase board_case(const Scene& scene, const SweepOptions& o, const Planned& p, const WidthRun& w) {
  TimingCase c = base_case(scene, o, w);
  c.label = p.config.label();
  c.board = p.check.options;
  c.board.bank_capacity_bytes = p.bank_capacity;
  return c;
}

// Compact banks promise identical passes; a batched or split step would break that promise.
void check_compact_banks(const Planned& p, const TimingOutcome& out) {
  if (p.bank_capacity == 0) return;
  const BatchingReport& b = out.report.board.batching;
  if (b.max_batches_per_step > 1 || b.face_sets > 1) {
    throw std::logic_error("compact banks batched " + p.config.label() + "; rerun with --full-banks");
  }
}

// ---- output ---------------------------------------------------------------------------------------

std::string cell(const SweepRow& r) {
  char text[16];
  if (r.validity == Validity::does_not_fit) return "fit";
  if (r.validity == Validity::too_few_banks) return "banks";
  if (r.validity != Validity::ok) return "-";
  std::snprintf(text, sizeof text, "%.3f", r.simulated_seconds);
  return text;
}

// 1,2,3,5 -> "1-3,5".
std::string ranges(const std::vector<unsigned>& values) {
  std::string text;
  for (std::size_t i = 0; i < values.size();) {
    std::size_t j = i;
    while (j + 1 < values.size() && values[j + 1] == values[j] + 1) ++j;
    text += (text.empty() ? "" : ",") + std::to_string(values[i]) + (j > i ? "-" + std::to_string(values[j]) : "");
    i = j + 1;
  }
  return text;
}

// One lanes x banks block of simulated seconds per device, width and driver (rows are enumerated
// device, width, driver, lanes, banks: each block is contiguous).
void print_blocks(const std::vector<SweepRow>& rows, const std::vector<int>& banks) {
  const std::size_t block = banks.size();
  for (std::size_t first = 0; first < rows.size();) {
    const SweepConfig& c = rows[first].config;
    std::printf("\n%s, %d-bit, %s driver: simulated seconds (fit: lanes do not fit; banks: too few banks)\n",
                c.device.c_str(), c.bits, c.concurrent ? "concurrent" : "serial");
    std::printf("  lanes \\ banks");
    for (int b : banks) std::printf(" %8d", b);
    std::printf("\n");
    const SweepRow* best = nullptr;
    std::size_t end = first;
    while (end < rows.size() && rows[end].config.device == c.device && rows[end].config.bits == c.bits &&
           rows[end].config.concurrent == c.concurrent)
      ++end;
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
      }
      std::printf("\n");
    }
    if (!unfit.empty()) std::printf("  lanes %s: do not fit the device\n", ranges(unfit).c_str());
    if (best) {
      std::printf("  fastest: %u lanes, %u banks: %.3f s, %.2fx one lane, %.2fx software; bottleneck %s\n",
                  best->config.lanes, best->config.banks, best->simulated_seconds, best->speedup_vs_one_lane,
                  best->speedup_vs_software, best->bottleneck.c_str());
    }
    first = end;
  }
}

nlohmann::ordered_json sweep_json(const SweepOptions& o, const Scene& scene, const std::map<int, WidthRun>& widths,
                                  const std::map<int, double>& software, const std::map<std::string, std::uint64_t>& capacity,
                                  const std::vector<SweepRow>& rows) {
  nlohmann::ordered_json j;
  j["schema"] = "rc2000sim.sweep/1";
  j["scene"] = {{"name", scene.name},
                {"source", o.scene.file.empty() ? "embedded:cornell-box" : o.scene.file},
                {"faces", scene.faces.size()},
                {"patches", scene.patches.size()}};
  j["solver"] = {{"paper_faithful", o.paper_faithful}, {"steps_policy", o.steps}, {"convergence", o.convergence},
                 {"visibility", o.visibility}};
  j["host_profile"] = o.host;
  nlohmann::ordered_json w = nlohmann::ordered_json::array();
  for (const auto& [bits, run] : widths) {
    w.push_back({{"bits", bits},
                 {"steps", run.steps},
                 {"convergence_step", run.functional.convergence_step > 0  // null: not within the replayed steps
                                          ? nlohmann::ordered_json(run.functional.convergence_step)
                                          : nlohmann::ordered_json()},
                 {"max_segments_per_step", run.max_segments},
                 {"software_seconds", software.at(bits)}});
  }
  j["widths"] = w;
  nlohmann::ordered_json banks;
  for (const auto& [device, bytes] : capacity) banks[device] = bytes;
  j["modelled_bank_capacity_bytes"] = banks;
  j["bank_capacity_note"] =
      "0: the profile's banks. Otherwise banks of this size, which change no pass, transfer or time for this "
      "scene (no step batches with either size; studies/config_sweep.cpp), to keep the model's memory small";
  nlohmann::ordered_json records = nlohmann::ordered_json::array();
  for (const SweepRow& r : rows) records.push_back(sweep_row_json(r));
  j["rows"] = records;
  return j;
}

// One line per key and per row: the file stays as diff-able as the CSV and a third of dump(2)'s size.
void write_json(std::ostream& out, const nlohmann::ordered_json& j) {
  out << "{\n";
  for (auto it = j.begin(); it != j.end(); ++it) {
    out << "  " << nlohmann::json(it.key()).dump() << ": ";
    if (it.key() != "rows") {
      out << it.value().dump() << ",\n";
      continue;
    }
    out << "[\n";
    for (std::size_t i = 0; i < it.value().size(); ++i)
      out << "    " << it.value()[i].dump() << (i + 1 < it.value().size() ? ",\n" : "\n");
    out << "  ]" << (std::next(it) != j.end() ? ",\n" : "\n");
  }
  out << "}\n";
}

// ---- the command ----------------------------------------------------------------------------------

SweepAxes parse_axes(const SweepOptions& o) {
  SweepAxes a;
  a.devices = parse_name_list(o.devices, "--devices");
  a.bits = parse_int_list(o.bits, "--bits", 7, 31);
  a.concurrent = parse_concurrency(o.concurrent);
  a.lanes = parse_int_list(o.lanes, "--lanes", 1, 255);  // the CONFIG register holds 8 bits of each
  a.banks = parse_int_list(o.banks, "--banks", 1, 255);
  return a;
}

// Every combination with its verdict, in enumeration order.
std::vector<Planned> plan_sweep(const SweepAxes& axes, const ConfigChecker& checker) {
  std::vector<Planned> plan;
  for (const SweepConfig& c : enumerate_configs(axes)) plan.push_back({c, checker.check(c)});
  return plan;
}

std::map<int, WidthRun> record_widths(const SweepOptions& o, const Scene& scene, const std::vector<int>& bits,
                                      ProgressLine& progress) {
  const StepsChoice steps = parse_steps(o.steps);
  int fixed_steps = steps.kind == StepsChoice::Kind::fixed ? steps.steps : 0;
  if (steps.kind == StepsChoice::Kind::paper) {
    fixed_steps = paper_steps(o, scene);
    if (fixed_steps == 0 && !o.quiet)
      std::fprintf(stderr, "note: the scene is not one of Table 2's; --steps paper falls back to converge\n");
  }
  std::map<int, WidthRun> widths;
  for (int b : bits) {
    progress.update("solving %zu patches at %d bits%-20s", scene.patches.size(), b, "");
    widths.emplace(b, record_width(o, scene, b, fixed_steps));
  }
  return widths;
}

// One software case per width first (in width order), then every combination that can exist;
// each planned combination learns its case's index.
std::vector<TimingCase> make_cases(const SweepOptions& o, const Scene& scene, const ConfigChecker& checker,
                                   const std::map<int, WidthRun>& widths, std::vector<Planned>& plan) {
  std::vector<TimingCase> cases;
  for (const auto& [bits, w] : widths) cases.push_back(software_case(scene, o, bits, w));
  for (Planned& p : plan) {
    if (p.check.validity != Validity::ok) continue;
    const WidthRun& w = widths.at(p.config.bits);
    if (!o.full_banks) p.bank_capacity = checker.compact_bank_capacity(p.config, w.max_segments, scene.faces.size());
    p.outcome = cases.size();
    cases.push_back(board_case(scene, o, p, w));
  }
  return cases;
}

std::vector<SweepRow> collect_rows(const std::vector<Planned>& plan, const ConfigChecker& checker,
                                   const std::map<int, WidthRun>& widths, const std::map<int, double>& software,
                                   const std::vector<TimingOutcome>& outcomes) {
  std::vector<SweepRow> rows;
  for (const Planned& p : plan) {
    const int replayed = widths.at(p.config.bits).steps;
    if (p.check.validity == Validity::ok) check_compact_banks(p, outcomes[p.outcome]);
    rows.push_back(p.check.validity == Validity::ok ? row_from_report(p.config, outcomes[p.outcome].report, replayed)
                                                    : invalid_row(p.config, p.check, replayed));
    rows.back().config.device = checker.device(p.config.device).name;  // a profile given by path shows its name
  }
  fill_speedups(rows, software);
  return rows;
}

std::map<std::string, std::uint64_t> bank_capacities(const std::vector<Planned>& plan, const ConfigChecker& checker) {
  std::map<std::string, std::uint64_t> capacity;
  for (const Planned& p : plan) {
    if (p.check.validity != Validity::ok) continue;
    std::uint64_t& bytes = capacity[checker.device(p.config.device).name];
    bytes = std::max(bytes, p.bank_capacity);
  }
  return capacity;
}

int run_sweep(const SweepOptions& o) {
  ProgressLine progress(!o.quiet);
  const SweepAxes axes = parse_axes(o);
  (void)parse_steps(o.steps);                         // a bad --steps fails before any work
  const ConfigChecker checker(axes.devices, o.host);  // and so do unknown profiles
  std::vector<Planned> plan = plan_sweep(axes, checker);
  const std::size_t valid = static_cast<std::size_t>(
      std::count_if(plan.begin(), plan.end(), [](const Planned& p) { return p.check.validity == Validity::ok; }));

  const Scene scene = prepare_scene(o.scene).scene;
  const std::map<int, WidthRun> widths = record_widths(o, scene, axes.bits, progress);
  const std::vector<TimingCase> cases = make_cases(o, scene, checker, widths, plan);
  progress.update("simulating %zu configurations (%zu cannot exist)%-10s", valid, plan.size() - valid, "");
  const std::vector<TimingOutcome> outcomes = run_timing_study(cases);
  progress.finish();

  std::map<int, double> software;  // the software cases come first, one per width in width order
  for (const auto& [bits, w] : widths) software[bits] = outcomes[software.size()].simulated_seconds;
  const std::vector<SweepRow> rows = collect_rows(plan, checker, widths, software, outcomes);

  std::filesystem::create_directories(o.out_dir);
  {
    std::ofstream csv(o.out_dir + "/sweep.csv");
    if (!csv) throw std::runtime_error(o.out_dir + "/sweep.csv: cannot open for writing");
    write_sweep_csv(csv, rows);
    std::ofstream json(o.out_dir + "/sweep.json");
    write_json(json, sweep_json(o, scene, widths, software, bank_capacities(plan, checker), rows));
  }
  std::printf("rc2000sim sweep: %s, %zu faces, %zu patches, %s, host %s\n", scene.name.c_str(), scene.faces.size(),
              scene.patches.size(), o.paper_faithful ? "paper-faithful (every segment)" : "receivers culled",
              o.host.c_str());
  for (const auto& [bits, w] : widths)
    std::printf("  %d-bit: %d steps replayed; software alone %.3f s\n", bits, w.steps, software.at(bits));
  std::printf("  %zu configurations: %zu simulated, %zu cannot exist\n", plan.size(), valid, plan.size() - valid);
  print_blocks(rows, axes.banks);
  plot("sweep.py", o.out_dir + "/sweep.csv", o.out_dir);
  std::printf("\n  wrote %s/sweep.csv, sweep.json and plots (%.1f s)\n", o.out_dir.c_str(), progress.seconds());
  return 0;
}

}  // namespace

void add_sweep_command(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<SweepOptions>();
  CLI::App* cmd = app.add_subcommand(
      "sweep", "What-if study: lanes x banks x width x device x driver for one scene (default: the paper's 280 faces, 1120 "
      "patches), one CSV row per configuration");
  add_scene_options(*cmd, o->scene);
  cmd->add_option("--steps", o->steps,
                  "paper (Table 2's count for a paper scene, else converge), converge (steps to --convergence, per "
                  "width) or a step count")
      ->capture_default_str();
  cmd->add_option("--convergence", o->convergence, "Convergence target of --steps converge")
      ->check(CLI::Range(0.0, 1.0))->capture_default_str();
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
  cmd->add_option("--host", o->host, "Host profile")->capture_default_str();
  cmd->add_option("--visibility", o->visibility, "Bit-exact backend that answers visibility once per width: fixed or fast")
      ->check(CLI::IsMember({"fixed", "fast"}))->capture_default_str();
  cmd->add_option("--out", o->out_dir, "Output folder for sweep.csv, sweep.json and the plots")->capture_default_str();
  cmd->add_flag("--full-banks", o->full_banks,
                "Model the profile's bank capacity even when smaller banks change nothing (more memory)");
  cmd->add_flag("--quiet", o->quiet, "No progress output");
  cmd->callback([o, cmd, &exit_code] {
    // A scene file is taken as it is unless refinement is asked for: the paper defaults are for
    // the embedded box.
    if (!o->scene.file.empty()) {
      const SceneOptions plain;
      if (cmd->count("--faces") == 0) o->scene.face_target = plain.face_target;
      if (cmd->count("--face-levels") == 0) o->scene.face_levels = plain.face_levels;
      if (cmd->count("--patch-levels") == 0) o->scene.patch_levels = plain.patch_levels;
    }
    exit_code = run_sweep(*o);
  });
}

}  // namespace rc
