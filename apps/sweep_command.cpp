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
#include "studies/sweep_study.h"
#include "studies/paper_workload.h"
#include "apps/plot.h"
#include "apps/progress.h"
#include "apps/report.h"
#include "studies/config_sweep.h"

namespace rc {

namespace {

// The study's settings (SweepSpec) and its axes as the command line spells them.
struct SweepOptions : SweepSpec {
  SweepOptions() { scene = paper_scene_options(280, 1120); }  // a Table 2 scene that sweeps in seconds
  std::string lanes = "1-16";
  std::string banks = "5-12";
  std::string bits = "15";
  std::string devices = "xc2v6000,virtex4-sx55,spartan3-5000";
  std::string concurrent = "on";
  std::string out_dir = "out/sweep";
};

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

// Sec 5.6's "lanes that fit" for every device and width swept, each rule.
struct SweptFit {
  int bits = 0;
  LanesThatFit estimates;
};

std::vector<SweptFit> swept_fits(const SweepSpec& spec) {
  std::vector<SweptFit> fits;
  for (const std::string& device : spec.axes.devices) {
    for (int bits : spec.axes.bits) fits.push_back({bits, lanes_that_fit(device, spec.host, bits)});
  }
  return fits;
}

nlohmann::ordered_json sweep_json(const SweepOptions& o, const Scene& scene, const std::map<int, WidthRun>& widths,
                                  const std::map<int, double>& software, const std::map<std::string, std::uint64_t>& capacity,
                                  const std::vector<SweptFit>& fits, const std::vector<SweepRow>& rows) {
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
  nlohmann::ordered_json estimates = nlohmann::ordered_json::array();
  for (const SweptFit& f : fits) {
    nlohmann::ordered_json e = {{"device", f.estimates.model.device}, {"bits", f.bits}};
    e.update(lanes_that_fit_json(f.estimates));
    estimates.push_back(e);
  }
  j["lanes_that_fit"] = estimates;
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

SweepSpec sweep_spec(const SweepOptions& o) {
  SweepSpec s = o;
  s.axes = parse_axes(o);
  return s;
}

int run_sweep(const SweepOptions& o) {
  ProgressLine progress(!o.quiet);
  const SweepSpec spec = sweep_spec(o);
  const SweepResult result =
      run_sweep_study(spec, [&](const std::string& what) { progress.update("%-60s", what.c_str()); });
  const Scene& scene = result.scene;
  progress.finish();
  const std::vector<SweepRow>& rows = result.rows;
  const std::map<int, WidthRun>& widths = result.widths;
  const std::map<int, double>& software = result.software_seconds;
  const std::vector<Planned>& plan = result.plan;
  const std::size_t valid = result.valid;

  const std::vector<SweptFit> fits = swept_fits(spec);
  std::filesystem::create_directories(o.out_dir);
  {
    std::ofstream csv(o.out_dir + "/sweep.csv");
    if (!csv) throw std::runtime_error(o.out_dir + "/sweep.csv: cannot open for writing");
    write_sweep_csv(csv, rows);
    std::ofstream json(o.out_dir + "/sweep.json");
    write_json(json, sweep_json(o, scene, widths, software, result.bank_capacities, fits, rows));
  }
  std::printf("rc2000sim sweep: %s, %zu faces, %zu patches, %s, host %s\n", scene.name.c_str(), scene.faces.size(),
              scene.patches.size(), o.paper_faithful ? "paper-faithful (every segment)" : "receivers culled",
              o.host.c_str());
  for (const auto& [bits, w] : widths)
    std::printf("  %d-bit: %d steps replayed; software alone %.3f s\n", bits, w.steps, software.at(bits));
  std::printf("  %zu configurations: %zu simulated, %zu cannot exist\n", plan.size(), valid, plan.size() - valid);
  print_blocks(rows, spec.axes.banks);
  std::printf("\n  sec 5.6, lanes that fit at full rate (docs/calibration.md):\n");
  for (const SweptFit& f : fits) std::printf("    %d-bit %s\n", f.bits, lanes_that_fit_line(f.estimates).c_str());
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
