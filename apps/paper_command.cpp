// `rc2000sim paper`: Table 2 and sec 5.6 of the paper, predicted by the model. Every scene is
// solved once (bit-exact 15-bit visibility, recorded); the four implementations and the bank
// variants replay it through their SystemC systems in one simulation. Only the software and
// single-pipeline columns were used for calibration; the rest are predictions.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <memory>

#include "apps/cli_options.h"
#include "apps/outputs.h"
#include "apps/paper_document.h"
#include "profiles/profile_document.h"
#include "board/throughput_estimates.h"
#include "host_sw/studies/paper_workload.h"
#include "apps/plot.h"
#include "apps/progress.h"
#include "apps/report.h"
#include "host_sw/outputs/run_report_json.h"
#include "host_sw/studies/calibration_variants.h"
#include "host_sw/studies/paper_prediction.h"
#include "host_sw/studies/workload.h"
#include "host_sw/studies/workload_json.h"
#include "host_sw/visibility/visibility_factory.h"

namespace rc {

namespace {

struct PaperOptions {
  std::string table = default_paper_table_path();
  std::string host = "athlon-mp-2600-calibrated";
  std::string out_dir = "out/paper";
  std::string docs_dir;  // also write paper.md and the plots here (e.g. docs/results)
  std::string variants = default_variants_path();  // every driver-model variant, for the spread
  std::string visibility = "fast";
  pipeline::ResourceSource resources = pipeline::ResourceSource::paper_fit;  // of the sec 5.6 searches' lane fits
  bool quiet = false;
};

using nlohmann::ordered_json;

ordered_json scene_record(const PaperTableRow& row) {
  ordered_json rec = {{"faces", row.scene.faces},
                      {"patches", row.scene.patches},
                      {"steps", row.scene.steps},
                      {"implementation", to_string(row.implementation)},
                      {"seconds", row.seconds},
                      {"role", row.calibration ? "calibration" : "prediction"},
                      {"paper_seconds", row.calibration ? ordered_json(row.paper_seconds()) : ordered_json()},
                      {"relative_residual", row.calibration ? ordered_json(row.relative_residual()) : ordered_json()},
                      {"fpga_busy_seconds", row.fpga_busy_seconds},
                      {"speedup_vs_software", row.speedup_vs_software},
                      {"steps_per_second", row.steps_per_second},
                      {"convergence_steps_ours", row.convergence_steps_ours}};
  if (!row.spread.empty()) {
    ordered_json list = ordered_json::array();
    for (const auto& [model, seconds] : row.spread) list.push_back({{"driver_model", model}, {"seconds", seconds}});
    rec["spread_min_seconds"] = row.spread_min_seconds;
    rec["spread_max_seconds"] = row.spread_max_seconds;
    rec["spread"] = list;
    ordered_json mechanisms = ordered_json::array();
    for (const auto& [model, seconds] : row.mechanisms) mechanisms.push_back({{"driver_model", model}, {"seconds", seconds}});
    rec["mechanisms"] = mechanisms;
    rec["range_min_seconds"] = row.range_min_seconds;
    rec["range_max_seconds"] = row.range_max_seconds;
    rec["interval_low_seconds"] = row.interval_low_seconds;
    rec["interval_high_seconds"] = row.interval_high_seconds;
  }
  return rec;
}

ordered_json nanojoules(double x) { return std::isnan(x) ? ordered_json() : ordered_json(x); }

ordered_json energy_json(const energy::FullRateEnergy& e) {
  ordered_json j = {{"estimate", e.estimate},
                    {"device", e.device},
                    {"lanes", e.lanes},
                    {"banks_powered", e.banks},
                    {"clock_mhz", e.clock_mhz},
                    {"intersections_per_s", e.intersections_per_s}};
  j["fpga_nj_per_intersection"] = nanojoules(e.fpga_nj);
  j["sram_nj_per_intersection"] = nanojoules(e.sram_nj);
  j["pci_nj_per_intersection"] = nanojoules(e.pci_nj);
  j["card_nj_per_intersection"] = nanojoules(e.card_nj);
  j["host_waiting_nj_per_intersection"] = nanojoules(e.host_waiting_nj);
  j["system_nj_per_intersection"] = nanojoules(e.system_nj);
  j["software_nj_per_intersection"] = nanojoules(e.software_nj);
  j["card_watts"] = nanojoules(e.card_watts);
  if (!e.missing.empty()) {
    j["energy_missing"] = e.missing;
    return j;
  }
  j["one_second_at_full_rate"] = energy_report_json(e.report);  // every term with its profile key and source
  return j;
}

// The one JSON writer of paper.json.
ordered_json paper_json(const PaperDocument& d) {
  ordered_json j;
  j["schema"] = "rc2000sim.paper/1";
  j["host_profile"] = d.host_profile;
  j["driver_model"] = d.driver_model;
  j["variants"] = d.variants;
  j["visibility"] = "bit-exact fixed point, 15 fractional bits, every segment against every face";
  ordered_json scenes = ordered_json::array(), estimates = ordered_json::array(), banks = ordered_json::array();
  for (const PaperTableRow& row : d.rows) scenes.push_back(scene_record(row));
  // Pairs: the paper's rule, then the model's estimate of the same question, and why they differ.
  for (std::size_t i = 0; i < d.paper_rule.size(); ++i) {
    estimates.push_back(estimate_json(d.paper_rule[i]));
    ordered_json model = estimate_json(d.model[i]);
    model["why_different"] = board::why_estimates_differ(d.paper_rule[i], d.model[i]);
    estimates.push_back(model);
  }
  for (const BankVariantRow& b : d.bank_variants) {
    banks.push_back({{"banks", b.variant.banks},
                     {"lanes", b.variant.lanes},
                     {"seconds", b.seconds},
                     {"fpga_busy_seconds", b.fpga_busy_seconds},
                     {"fpga_speedup_over_five_banks", b.fpga_speedup_over_five_banks},
                     {"run_speedup_over_five_banks", b.run_speedup_over_five_banks}});
  }
  ordered_json energy = ordered_json::array();
  for (const energy::FullRateEnergy& e : d.energy) energy.push_back(energy_json(e));
  j["prediction_interval"] = {
      {"method", "from the fastest to the slowest variant or mechanism (range_min/max_seconds), each bound divided "
                 "by 1 + a quantile of the calibration's left-out relative errors (docs/calibration.md, Prediction intervals)"},
      {"quantiles", {kIntervalQuantiles[0], kIntervalQuantiles[1]}},
      {"left_out_errors", d.left_out_errors},
      {"left_out_error_low", d.left_out_error_low},
      {"left_out_error_high", d.left_out_error_high}};
  // Each scene's workload (workload.h), recorded as report.json and sweep.json record theirs.
  ordered_json workloads = ordered_json::array();
  for (std::size_t i = 0; i < d.rows.size(); i += kPaperImplementations) {
    const PaperRow& s = d.rows[i].scene;
    workloads.push_back(workload_json(paper_workload(s), s.faces, s.patches, s.steps));
  }
  j["workloads"] = workloads;
  j["concurrent_mechanisms"] = {
      {"splits", "CPU/FPGA split, software tests balanced against the board on 1 or 2 CPUs (docs/calibration.md)"},
      {"pipelined", "the pipelined driver, alone and with the split on 2 CPUs (\"/chunks of N\" in a mechanism's name)"},
      {"pipelined_chunk_rule", kPipelinedChunkRule}};
  j["scene_records"] = scenes;
  j["estimate_records"] = estimates;
  j["energy_records"] = energy;
  // Per device: the paper's rule at its clock(s), the model's best searched design with its bound.
  j["device_estimates"] = sec56_devices_json(d.devices);
  j["device_search_resources"] = choice_name(d.resources);
  j["lanes_by_source"] = lanes_by_source_json(d.lanes_by_source);
  j["bank_variants"] = banks;
  j["summary"] = {{"average_overall_speedup", d.summary.average_overall_speedup},
                  {"largest_scene_overall_speedup", d.summary.largest_scene_overall_speedup},
                  {"average_steps_per_second_concurrent", d.summary.average_steps_per_second_concurrent},
                  {"overall_speedup_definition", "software seconds / concurrent seconds (two pipelines with the concurrent driver)"}};
  return j;
}

// Numbers as paper.json spells them (shortest text that reads back to the same double).
std::string json_number_text(double x) { return ordered_json(x).dump(); }

std::string paper_csv(const PaperDocument& d) {
  std::ostringstream out;
  out << "record,faces,patches,steps,implementation,seconds,paper_seconds,relative_residual,spread_min_seconds,"
         "spread_max_seconds,fpga_busy_seconds,speedup_vs_software,device,lanes,clock_mhz,intersections_per_s,"
         "bytes_per_cycle,gb_per_s,estimate,rule,fpga_nj,sram_nj,pci_nj,card_nj,host_waiting_nj,system_nj,software_nj,"
         "interval_low_seconds,interval_high_seconds\n";
  for (const PaperTableRow& s : d.rows) {
    out << "scene," << s.scene.faces << ',' << s.scene.patches << ',' << s.scene.steps << ',' << to_string(s.implementation)
        << ',' << json_number_text(s.seconds) << ',' << (s.calibration ? json_number_text(s.paper_seconds()) : "") << ','
        << (s.calibration ? json_number_text(s.relative_residual()) : "") << ','
        << (s.spread.empty() ? "" : json_number_text(s.spread_min_seconds)) << ','
        << (s.spread.empty() ? "" : json_number_text(s.spread_max_seconds)) << ',' << json_number_text(s.fpga_busy_seconds) << ','
        << json_number_text(s.speedup_vs_software) << ",,,,,,,,,,,,,,,,"
        << (s.spread.empty() ? "" : json_number_text(s.interval_low_seconds)) << ','
        << (s.spread.empty() ? "" : json_number_text(s.interval_high_seconds)) << "\n";
  }
  for (std::size_t i = 0; i < d.paper_rule.size(); ++i) {
    for (const board::PaperEstimate* e : {&d.paper_rule[i], &d.model[i]}) {
      out << "estimate,,,,,,,,,,," << json_number_text(e->speedup_vs_software) << ',' << e->device << ',' << e->lanes << ','
          << json_number_text(e->clock_mhz) << ',' << json_number_text(e->intersections_per_s) << ',' << json_number_text(e->bytes_per_cycle) << ','
          << json_number_text(e->gb_per_s) << ",\"" << e->estimate << "\"," << board::to_string(e->rule) << ",,,,,,,,,\n";
    }
  }
  auto nj = [](double x) { return std::isnan(x) ? std::string() : json_number_text(x); };
  for (const energy::FullRateEnergy& e : d.energy) {
    out << "energy,,,,,,,,,,,," << e.device << ',' << e.lanes << ',' << json_number_text(e.clock_mhz) << ','
        << json_number_text(e.intersections_per_s) << ",,,\"" << e.estimate << "\",model," << nj(e.fpga_nj) << ',' << nj(e.sram_nj)
        << ',' << nj(e.pci_nj) << ',' << nj(e.card_nj) << ',' << nj(e.host_waiting_nj) << ',' << nj(e.system_nj) << ','
        << nj(e.software_nj) << ",,\n";
  }
  return out.str();
}

// A withheld-column cell: the prediction and its interval (variants, mechanisms and the calibration's
// left-out errors).
std::string with_spread(const PaperTableRow& row) {
  char text[64];
  if (row.spread.empty()) {
    std::snprintf(text, sizeof text, "%7.1f", row.seconds);
  } else {
    std::snprintf(text, sizeof text, "%7.1f [%6.1f-%6.1f]", row.seconds, row.interval_low_seconds, row.interval_high_seconds);
  }
  return text;
}

void print_table(const PaperDocument& d) {
  std::printf("\nTable 2 (seconds; paper figures in brackets; * = calibration column; predictions with [an interval:\n"
              "the driver-model variants within %.0f%% of the best cross-validated error, the concurrent column's CPU/FPGA\n"
              "split and pipelined-driver mechanisms, widened by the %.0f%%-%.0f%% quantiles of the calibration's left-out errors, %+.1f%%..%+.1f%%])\n",
              100 * kVariantTolerance, 100 * kIntervalQuantiles[0], 100 * kIntervalQuantiles[1], 100 * d.left_out_error_low,
              100 * d.left_out_error_high);
  std::printf("%6s %7s %6s %6s | %17s | %17s | %24s | %24s | %7s\n", "faces", "patches", "steps", "ours", "software*",
              "one pipe*", "two pipes", "concurrent", "speedup");
  for (std::size_t i = 0; i + 3 < d.rows.size(); i += kPaperImplementations) {
    const PaperTableRow &sw = d.rows[i], &one = d.rows[i + 1], &two = d.rows[i + 2], &con = d.rows[i + 3];
    const PaperRow& s = sw.scene;
    char ours[16];
    std::snprintf(ours, sizeof ours, sw.convergence_steps_ours ? "%d" : ">%d",
                  sw.convergence_steps_ours ? sw.convergence_steps_ours : s.steps + s.steps / 10);
    std::printf("%6d %7d %6d %6s | %7.1f [%7.1f] | %7.1f [%7.1f] | %24s | %24s | %6.2fx\n", s.faces, s.patches, s.steps,
                ours, sw.seconds, s.software_seconds, one.seconds, s.one_pipe_seconds, with_spread(two).c_str(),
                with_spread(con).c_str(), con.speedup_vs_software);
  }
  std::printf("\nSec 5.6 estimates (15-bit pipeline): the paper's rule on its printed figures, and the model\n");
  std::printf("  %-24s %-14s %-5s %5s %7s %11s %7s %8s %7s %9s\n", "estimate", "device", "rule", "lanes", "MHz", "int/s",
              "B/int", "B/cycle", "GB/s", "speedup");
  for (std::size_t i = 0; i < d.paper_rule.size(); ++i) {
    for (const board::PaperEstimate* e : {&d.paper_rule[i], &d.model[i]}) {
      std::printf("  %-24s %-14s %-5s %5d %7.1f %11.4g %7.3f %8.3f %7.2f %8.2fx  %s\n", e->estimate.c_str(),
                  e->device.c_str(), board::to_string(e->rule), e->lanes, e->clock_mhz, e->intersections_per_s,
                  e->bytes_per_intersection, e->bytes_per_cycle, e->gb_per_s, e->speedup_vs_software, e->note.c_str());
    }
    std::printf("    why they differ: %s\n", board::why_estimates_differ(d.paper_rule[i], d.model[i]).c_str());
  }
  std::printf("  software rates: paper rule %.4g int/s (Table 2's peak), model %.4g int/s (calibrated test)\n",
              d.paper_rule[0].software_rate, d.model[0].software_rate);
  std::printf("\nSec 5.6 in energy: nJ per intersection at full rate (model estimates; docs/energy.md)\n");
  std::printf("  %-24s %-14s %5s %5s %9s %8s %8s %8s %8s %10s %8s\n", "estimate", "device", "lanes", "banks", "int/s",
              "fpga", "sram", "pci", "card", "+host wait", "software");
  for (const energy::FullRateEnergy& e : d.energy) {
    if (!e.missing.empty()) {
      std::printf("  %-24s %-14s no energy figures: %s\n", e.estimate.c_str(), e.device.c_str(), e.missing.c_str());
      continue;
    }
    std::printf("  %-24s %-14s %5d %5u %9.3g %8.3f %8.3f %8.3f %8.3f %10.3f %8.1f\n", e.estimate.c_str(), e.device.c_str(),
                e.lanes, e.banks, e.intersections_per_s, e.fpga_nj, e.sram_nj, e.pci_nj, e.card_nj, e.system_nj,
                e.software_nj);
  }
  std::printf("\nSec 4.1 bank variants (largest scene, 15 bits)\n");
  for (const BankVariantRow& b : d.bank_variants) {
    std::printf("  %u banks, %u lanes: %8.1f s, FPGA busy %8.1f s, FPGA speedup over 5 banks %.3fx\n", b.variant.banks,
                b.variant.lanes, b.seconds, b.fpga_busy_seconds, b.fpga_speedup_over_five_banks);
  }
}

}  // namespace

namespace {

// The model's sec 5.6 designs with lanes, in joules: the designs of the throughput table, no others.
std::vector<energy::FullRateEnergy> full_rate_energy_rows(const std::vector<board::PaperEstimate>& model,
                                                          const HostProfile& host) {
  constexpr int kBits = 15;  // the paper's estimates are of the 15-bit pipeline
  std::vector<board::PaperEstimate> designs;
  for (const board::PaperEstimate& e : model)
    if (e.lanes > 0) designs.push_back(e);
  std::vector<energy::FullRateEnergy> rows;
  for (const board::PaperEstimate& e : designs) {
    const board::DeviceProfile device = board::find_device_profile(e.device);
    rows.push_back(energy::full_rate_energy(e, device, energy::load_energy_tables(&device, host.document, host.file), kBits));
  }
  return rows;
}

int run_paper(const PaperOptions& o) {
  const std::string json_path = o.out_dir + "/paper.json", csv_path = o.out_dir + "/paper.csv";
  const std::string markdown_path = o.docs_dir + "/paper.md";
  const std::string pictures = o.docs_dir.empty() ? o.out_dir : o.docs_dir + "/paper";
  Outputs outputs;
  outputs.own_folder(o.out_dir, "paper");
  for (const std::string& p : {json_path, csv_path, o.out_dir + "/roofline.csv", pictures + "/table2.png",
                               pictures + "/table2-intervals.png"})
    outputs.expect(p);
  if (!o.docs_dir.empty()) outputs.expect(markdown_path);
  ProgressLine progress(!o.quiet);
  const std::vector<PaperRow> rows = load_paper_table(o.table);
  const HostProfile host = find_host_profile(o.host);  // fails early with a clear message
  const std::vector<CalibratedVariant> variants = load_calibrated_variants(o.variants);
  std::vector<PaperScene> scenes =
      prepare_paper_scenes(rows, o.visibility, 15, [&](const std::string& what) { progress.update("%-40s", what.c_str()); });
  progress.update("simulating the configurations%-20s", "");
  const double functional_seconds = progress.seconds();
  PlotProcess plotter("paper.py");  // the interpreter loads while the study runs
  const PaperPrediction r = predict_paper(scenes, rows, o.host, host, variants, o.resources);
  const double study_seconds = progress.seconds() - functional_seconds;
  progress.finish();

  PaperDocument document;
  document.rows = table_rows(r);
  document.paper_rule = r.paper_rule;
  document.model = r.model;
  document.bank_variants = bank_variant_rows(r);
  document.energy = full_rate_energy_rows(r.model, host);
  document.summary = summarize(r);
  const double paper_rate = measured_peak_software_rate(rows);
  document.devices = sec56_device_rows(r, paper_rate, r.model.front().software_rate);
  document.rooflines = sec56_rooflines(r, paper_rate);
  document.lanes_by_source = sec56_lanes_by_source();
  document.resources = o.resources;
  document.host_profile = o.host;
  document.driver_model = host.driver_model.name();
  document.left_out_error_low = r.left_out_error_low;
  document.left_out_error_high = r.left_out_error_high;
  document.left_out_errors = r.left_out_errors;
  // Named as configs/... when in the config folder, wherever that is (source tree or installed).
  const std::string config_dir = profiles::default_config_dir() + "/";
  document.variants = o.variants.rfind(config_dir, 0) == 0 ? "configs/" + o.variants.substr(config_dir.size()) : o.variants;
  outputs.add(json_path, pretty_json(paper_json(document)));
  outputs.add(csv_path, paper_csv(document));
  outputs.add(o.out_dir + "/roofline.csv", roofline_csv(document.rooflines));  // paper.py draws it beside paper.csv
  if (!o.docs_dir.empty()) outputs.add(markdown_path, paper_markdown(document));
  outputs.write();
  print_table(document);
  print_sec56_devices(document.devices);
  print_lanes_by_source(document.lanes_by_source);
  std::printf("\n  average overall speedup %.2fx, largest scene %.2fx (software / concurrent)\n",
              document.summary.average_overall_speedup, document.summary.largest_scene_overall_speedup);
  std::filesystem::create_directories(pictures);  // the plots' folder, now that the data is written
  plotter.draw(csv_path, pictures);
  const bool drawn = plotter.finish();
  std::printf("  wall: functional visibility and solver %.2f s, SystemC timing of %zu systems %.2f s (%.0f%%), total %.2f s\n",
              functional_seconds, r.outcomes.size(), study_seconds, 100.0 * study_seconds / progress.seconds(), progress.seconds());
  std::printf("  wrote %s%s\n", listed(outputs.paths()).c_str(),
              drawn ? (" and the plots in " + pictures).c_str() : "");
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
  cmd->add_option("--out", o->out_dir, "Output folder for paper.csv, paper.json and plots")
      ->check(output_path())->capture_default_str();
  cmd->add_option("--docs", o->docs_dir, "Also write paper.md and its plots here (e.g. docs/results)")
      ->check(output_path());
  cmd->add_option("--visibility", o->visibility, "Bit-exact backend that answers visibility once per scene: fixed or fast")
      ->check(CLI::IsMember(choice_names<BitExactVisibility>()))->capture_default_str();
  add_resources_option(*cmd, o->resources, "Sec 5.6's design searches: ");
  cmd->add_flag("--quiet", o->quiet, "No progress output");
  add_jobs_option(*cmd, "the scenes solved side by side, the timing study's processes");
  cmd->callback([o, cmd, &exit_code] {
    // Defaults in the config folder chosen at run time (--configs, after these defaults were made).
    if (!given(*cmd, "--table")) o->table = default_paper_table_path();
    if (!given(*cmd, "--variants")) o->variants = default_variants_path();
    const std::string where = o->out_dir + "/" + (o->docs_dir.empty() ? "" : " and " + o->docs_dir + "/");
    exit_code = run_guarded("paper", where, [&] { return run_paper(*o); });
  });
}

}  // namespace rc
