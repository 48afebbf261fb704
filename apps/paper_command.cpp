// `rc2000sim paper`: Table 2 and sec 5.6 of the paper, predicted by the model. Every scene is
// solved once (bit-exact 15-bit visibility, recorded); the four implementations and the bank
// variants replay it through their SystemC systems in one simulation. Only the software and
// single-pipeline columns were used for calibration; the rest are predictions.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>

#include "apps/cli_options.h"
#include "board/throughput_estimates.h"
#include "studies/paper_workload.h"
#include "apps/plot.h"
#include "apps/progress.h"
#include "studies/calibration_variants.h"
#include "studies/paper_prediction.h"

namespace rc {

namespace {

struct PaperOptions {
  std::string table = default_paper_table_path();
  std::string host = "athlon-mp-2600-calibrated";
  std::string out_dir = "out/paper";
  std::string docs_dir;  // also write paper.md and the plots here (e.g. docs/results)
  std::string variants = default_variants_path();  // every driver-model variant, for the spread
  std::string visibility = "fast";
  bool quiet = false;
};

double paper_seconds(const PaperRow& row, int impl) {
  return impl == 0 ? row.software_seconds : impl == 1 ? row.one_pipe_seconds : NAN;
}

nlohmann::ordered_json scene_records(const PaperPrediction& r) {
  nlohmann::ordered_json records = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < r.scenes->size(); ++i) {
    const PaperScene& s = (*r.scenes)[i];
    for (int impl = 0; impl < kPaperImplementations; ++impl) {
      const TimingOutcome& o = r.at(i, impl);
      const double paper = paper_seconds(s.row, impl);
      nlohmann::ordered_json rec = {{"faces", s.row.faces},
                                    {"patches", s.row.patches},
                                    {"steps", s.row.steps},
                                    {"implementation", to_string(PaperImplementation(impl))},
                                    {"seconds", o.simulated_seconds},
                                    {"role", impl < 2 ? "calibration" : "prediction"},
                                    {"paper_seconds", std::isnan(paper) ? nlohmann::ordered_json() : nlohmann::ordered_json(paper)},
                                    {"relative_residual", std::isnan(paper) ? nlohmann::ordered_json()
                                                                            : nlohmann::ordered_json((o.simulated_seconds - paper) / paper)},
                                    {"fpga_busy_seconds", fpga_busy(o)},
                                    {"speedup_vs_software", r.at(i, 0).simulated_seconds / o.simulated_seconds},
                                    {"steps_per_second", s.row.steps / o.simulated_seconds},
                                    {"convergence_steps_ours", s.convergence_steps}};
      const auto spread = r.spread_of(i, impl);
      if (!spread.empty()) {
        double lo = spread[0].second, hi = lo;
        nlohmann::ordered_json list = nlohmann::ordered_json::array();
        for (const auto& [model, seconds] : spread) {
          lo = std::min(lo, seconds);
          hi = std::max(hi, seconds);
          list.push_back({{"driver_model", model}, {"seconds", seconds}});
        }
        rec["spread_min_seconds"] = lo;
        rec["spread_max_seconds"] = hi;
        rec["spread"] = list;
      }
      records.push_back(rec);
    }
  }
  return records;
}

nlohmann::ordered_json estimate_record(const board::PaperEstimate& e) {
  return {{"estimate", e.estimate},
          {"rule", board::to_string(e.rule)},
          {"device", e.device},
          {"lanes", e.lanes},
          {"clock_mhz", e.clock_mhz},
          {"intersections_per_s", e.intersections_per_s},
          {"bytes_per_intersection", e.bytes_per_intersection},
          {"bytes_per_cycle", e.bytes_per_cycle},
          {"gb_per_s", e.gb_per_s},
          {"software_rate", e.software_rate},
          {"speedup_vs_software", e.speedup_vs_software},
          {"note", e.note}};
}

// Pairs: the paper's rule, then the model's estimate of the same question, and why they differ.
nlohmann::ordered_json estimate_records(const PaperPrediction& r) {
  nlohmann::ordered_json records = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < r.paper_rule.size(); ++i) {
    records.push_back(estimate_record(r.paper_rule[i]));
    nlohmann::ordered_json model = estimate_record(r.model[i]);
    model["why_different"] = board::why_estimates_differ(r.paper_rule[i], r.model[i]);
    records.push_back(model);
  }
  return records;
}

nlohmann::ordered_json bank_variant_records(const PaperPrediction& r) {
  nlohmann::ordered_json records = nlohmann::ordered_json::array();
  const TimingOutcome& base = r.bank_variant(0);
  for (std::size_t v = 0; v < std::size(kBankVariants); ++v) {
    const TimingOutcome& o = r.bank_variant(v);
    records.push_back({{"banks", kBankVariants[v].banks},
                       {"lanes", kBankVariants[v].lanes},
                       {"seconds", o.simulated_seconds},
                       {"fpga_busy_seconds", fpga_busy(o)},
                       {"fpga_speedup_over_five_banks", fpga_busy(base) / fpga_busy(o)},
                       {"run_speedup_over_five_banks", base.simulated_seconds / o.simulated_seconds}});
  }
  return records;
}

nlohmann::ordered_json summary(const PaperPrediction& r) {
  double speedup_sum = 0, steps_per_s = 0;
  const std::size_t n = r.scenes->size();
  for (std::size_t i = 0; i < n; ++i) {
    speedup_sum += r.at(i, 0).simulated_seconds / r.at(i, 3).simulated_seconds;
    steps_per_s += (*r.scenes)[i].row.steps / r.at(i, 3).simulated_seconds;
  }
  return {{"average_overall_speedup", speedup_sum / n},
          {"largest_scene_overall_speedup", r.at(n - 1, 0).simulated_seconds / r.at(n - 1, 3).simulated_seconds},
          {"average_steps_per_second_concurrent", steps_per_s / n},
          {"overall_speedup_definition", "software seconds / concurrent seconds (two pipelines with the concurrent driver)"}};
}

void write_csv(const std::string& path, const nlohmann::ordered_json& scenes, const nlohmann::ordered_json& estimates) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error(path + ": cannot open for writing");
  auto field = [](const nlohmann::ordered_json& v) { return v.is_null() ? std::string() : v.is_string() ? v.get<std::string>() : v.dump(); };
  auto optional = [&](const nlohmann::ordered_json& j, const char* key) { return j.contains(key) ? field(j[key]) : std::string(); };
  out << "record,faces,patches,steps,implementation,seconds,paper_seconds,relative_residual,spread_min_seconds,"
         "spread_max_seconds,fpga_busy_seconds,speedup_vs_software,device,lanes,clock_mhz,intersections_per_s,"
         "bytes_per_cycle,gb_per_s,estimate,rule\n";
  for (const auto& s : scenes) {
    out << "scene," << s["faces"] << ',' << s["patches"] << ',' << s["steps"] << ',' << field(s["implementation"]) << ','
        << s["seconds"] << ',' << field(s["paper_seconds"]) << ',' << field(s["relative_residual"]) << ','
        << optional(s, "spread_min_seconds") << ',' << optional(s, "spread_max_seconds") << ',' << s["fpga_busy_seconds"]
        << ',' << s["speedup_vs_software"] << ",,,,,,,,\n";
  }
  for (const auto& e : estimates) {
    out << "estimate,,,,,,,,,,," << e["speedup_vs_software"] << ',' << field(e["device"]) << ',' << e["lanes"] << ','
        << e["clock_mhz"] << ',' << e["intersections_per_s"] << ',' << e["bytes_per_cycle"] << ',' << e["gb_per_s"] << ",\""
        << field(e["estimate"]) << "\"," << field(e["rule"]) << "\n";
  }
}

std::string with_spread(const PaperPrediction& r, std::size_t scene, int impl) {
  const auto spread = r.spread_of(scene, impl);
  char text[64];
  if (spread.empty()) {
    std::snprintf(text, sizeof text, "%7.1f", r.at(scene, impl).simulated_seconds);
  } else {
    double lo = spread[0].second, hi = lo;
    for (const auto& [model, seconds] : spread) lo = std::min(lo, seconds), hi = std::max(hi, seconds);
    std::snprintf(text, sizeof text, "%7.1f [%6.1f-%6.1f]", r.at(scene, impl).simulated_seconds, lo, hi);
  }
  return text;
}

void print_table(const PaperPrediction& r) {
  std::printf("\nTable 2 (seconds; paper figures in brackets; * = calibration column; predictions with [the spread of\n"
              "the driver-model variants within %.0f%% of the best cross-validated error])\n", 100 * kVariantTolerance);
  std::printf("%6s %7s %6s %6s | %17s | %17s | %24s | %24s | %7s\n", "faces", "patches", "steps", "ours", "software*",
              "one pipe*", "two pipes", "concurrent", "speedup");
  for (std::size_t i = 0; i < r.scenes->size(); ++i) {
    const PaperScene& s = (*r.scenes)[i];
    char ours[16];
    std::snprintf(ours, sizeof ours, s.convergence_steps ? "%d" : ">%d", s.convergence_steps ? s.convergence_steps : s.recorded_steps);
    std::printf("%6d %7d %6d %6s | %7.1f [%7.1f] | %7.1f [%7.1f] | %24s | %24s | %6.2fx\n", s.row.faces, s.row.patches,
                s.row.steps, ours, r.at(i, 0).simulated_seconds, s.row.software_seconds, r.at(i, 1).simulated_seconds,
                s.row.one_pipe_seconds, with_spread(r, i, 2).c_str(), with_spread(r, i, 3).c_str(),
                r.at(i, 0).simulated_seconds / r.at(i, 3).simulated_seconds);
  }
  std::printf("\nSec 5.6 estimates (15-bit pipeline): the paper's rule on its printed figures, and the model\n");
  std::printf("  %-24s %-14s %-5s %5s %7s %11s %7s %8s %7s %9s\n", "estimate", "device", "rule", "lanes", "MHz", "int/s",
              "B/int", "B/cycle", "GB/s", "speedup");
  for (std::size_t i = 0; i < r.paper_rule.size(); ++i) {
    for (const board::PaperEstimate* e : {&r.paper_rule[i], &r.model[i]}) {
      std::printf("  %-24s %-14s %-5s %5d %7.1f %11.4g %7.3f %8.3f %7.2f %8.2fx  %s\n", e->estimate.c_str(),
                  e->device.c_str(), board::to_string(e->rule), e->lanes, e->clock_mhz, e->intersections_per_s,
                  e->bytes_per_intersection, e->bytes_per_cycle, e->gb_per_s, e->speedup_vs_software, e->note.c_str());
    }
    std::printf("    why they differ: %s\n", board::why_estimates_differ(r.paper_rule[i], r.model[i]).c_str());
  }
  std::printf("  software rates: paper rule %.4g int/s (Table 2's peak), model %.4g int/s (calibrated test)\n",
              r.paper_rule[0].software_rate, r.model[0].software_rate);
  std::printf("\nSec 4.1 bank variants (largest scene, 15 bits)\n");
  for (std::size_t v = 0; v < std::size(kBankVariants); ++v) {
    const TimingOutcome& o = r.bank_variant(v);
    std::printf("  %u banks, %u lanes: %8.1f s, FPGA busy %8.1f s, FPGA speedup over 5 banks %.3fx\n", kBankVariants[v].banks,
                kBankVariants[v].lanes, o.simulated_seconds, fpga_busy(o), fpga_busy(r.bank_variant(0)) / fpga_busy(o));
  }
}

}  // namespace

void write_paper_markdown(const std::string& path, const nlohmann::ordered_json& json, const std::string& host);

namespace {

int run_paper(const PaperOptions& o) {
  ProgressLine progress(!o.quiet);
  const std::vector<PaperRow> rows = load_paper_table(o.table);
  const HostProfile host = find_host_profile(o.host);  // fails early with a clear message
  const std::vector<CalibratedVariant> variants = load_calibrated_variants(o.variants);
  std::vector<PaperScene> scenes =
      prepare_paper_scenes(rows, o.visibility, 15, [&](const std::string& what) { progress.update("%-40s", what.c_str()); });
  progress.update("simulating the configurations%-20s", "");
  const double functional_seconds = progress.seconds();
  PlotProcess plotter("paper.py");  // the interpreter loads while the study runs
  const PaperPrediction r = predict_paper(scenes, rows, o.host, host, variants);
  const double study_seconds = progress.seconds() - functional_seconds;
  progress.finish();

  nlohmann::ordered_json json;
  json["schema"] = "rc2000sim.paper/1";
  json["host_profile"] = o.host;
  json["driver_model"] = host.driver_model.name();
  const std::string source_dir = std::string(RC_SOURCE_DIR) + "/";
  json["variants"] = o.variants.rfind(source_dir, 0) == 0 ? o.variants.substr(source_dir.size()) : o.variants;
  json["visibility"] = "bit-exact fixed point, 15 fractional bits, every segment against every face";
  json["scene_records"] = scene_records(r);
  json["estimate_records"] = estimate_records(r);
  json["bank_variants"] = bank_variant_records(r);
  json["summary"] = summary(r);
  std::filesystem::create_directories(o.out_dir);
  std::ofstream(o.out_dir + "/paper.json") << json.dump(2) << "\n";
  write_csv(o.out_dir + "/paper.csv", json["scene_records"], json["estimate_records"]);
  print_table(r);
  std::printf("\n  average overall speedup %.2fx, largest scene %.2fx (software / concurrent)\n",
              json["summary"]["average_overall_speedup"].get<double>(), json["summary"]["largest_scene_overall_speedup"].get<double>());
  if (!o.docs_dir.empty()) {
    std::filesystem::create_directories(o.docs_dir + "/paper");
    plotter.draw(o.out_dir + "/paper.csv", o.docs_dir + "/paper");
    write_paper_markdown(o.docs_dir + "/paper.md", json, o.host);
  } else {
    plotter.draw(o.out_dir + "/paper.csv", o.out_dir);
  }
  plotter.finish();
  std::printf("  wall: functional visibility and solver %.2f s, SystemC timing of %zu systems %.2f s (%.0f%%), total %.2f s\n",
              functional_seconds, r.outcomes.size(), study_seconds, 100.0 * study_seconds / progress.seconds(), progress.seconds());
  std::printf("  wrote %s/paper.json, paper.csv%s\n", o.out_dir.c_str(),
              o.docs_dir.empty() ? "" : (", " + o.docs_dir + "/paper.md").c_str());
  return 0;
}

}  // namespace

void add_paper_command(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<PaperOptions>();
  CLI::App* cmd = app.add_subcommand("paper", "Predict the paper's Table 2 and sec 5.6 with the calibrated model");
  cmd->add_option("--table", o->table, "Measured Table 2 columns")->check(CLI::ExistingFile)->capture_default_str();
  cmd->add_option("--host", o->host, "Host profile (rc2000sim calibrate writes the default)")->capture_default_str();
  cmd->add_option("--variants", o->variants, "Calibrated driver-model variants (rc2000sim calibrate writes them)")
      ->check(CLI::ExistingFile)->capture_default_str();
  cmd->add_option("--out", o->out_dir, "Output folder for paper.csv, paper.json and plots")->capture_default_str();
  cmd->add_option("--docs", o->docs_dir, "Also write paper.md and its plots here (e.g. docs/results)");
  cmd->add_option("--visibility", o->visibility, "Bit-exact backend that answers visibility once per scene: fixed or fast")
      ->check(CLI::IsMember({"fixed", "fast"}))->capture_default_str();
  cmd->add_flag("--quiet", o->quiet, "No progress output");
  cmd->callback([o, &exit_code] { exit_code = run_paper(*o); });
}

}  // namespace rc
