// `rc2000sim calibrate`: fits the host CPU cost model to the paper's Table 2 software and
// single-pipeline columns (and nothing else), and writes the calibrated host profile.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>

#include "apps/cli_options.h"
#include "apps/paper_workload.h"
#include "apps/progress.h"
#include "studies/calibration.h"
#include "studies/calibration_variants.h"

namespace rc {

namespace {

struct CalibrateOptions {
  std::string table = default_paper_table_path();
  std::string base = "athlon-mp-2600";
  std::string out = std::string(RC_SOURCE_DIR) + "/configs/hosts/athlon-mp-2600-calibrated.json";
  std::string variants_out = default_variants_path();
  std::string name = "athlon-mp-2600-calibrated";
  std::string visibility = "fast";
  bool quiet = false;
};

// Per scene the software run (the driver model does not touch it), then every variant's
// single-pipeline run of every scene.
std::vector<TimingCase> calibration_cases(const std::vector<PaperScene>& scenes, const HostProfile& base,
                                          const std::vector<HostProfile>& variants) {
  std::vector<TimingCase> cases;
  for (const PaperScene& s : scenes) {
    TimingCase c = paper_timing_case(s, PaperImplementation::Software, base.name);
    c.host_profile = base;
    cases.push_back(c);
  }
  for (const HostProfile& v : variants) {
    for (const PaperScene& s : scenes) {
      TimingCase c = paper_timing_case(s, PaperImplementation::OnePipe, base.name);
      c.label += " " + v.driver_model.name();
      c.board.host_profile = v;
      cases.push_back(c);
    }
  }
  return cases;
}

void print_variants(const std::vector<VariantCalibration>& variants, std::size_t best) {
  std::printf("\nDriver-model variants (docs/calibration.md): fit to all 16 runs, and leave-one-out cross-validation\n");
  std::printf("  %-32s", "variant (unit/transfer/faces)");
  for (int g = 0; g < kCostGroups; ++g) std::printf(" %14s", to_string(CostGroup(g)).c_str());
  std::printf(" %8s %8s %8s\n", "fit rms", "CV mean", "CV worst");
  for (std::size_t i = 0; i < variants.size(); ++i) {
    const VariantCalibration& v = variants[i];
    const std::string name = v.used.driver_model.name();
    std::printf("  %-32s", name.substr(0, name.rfind('/')).c_str());
    for (int g = 0; g < kCostGroups; ++g) std::printf(" %14.4g", v.fit.scale[g]);
    std::printf(" %7.1f%% %7.1f%% %7.1f%% %s\n", 100 * v.fit.rms_relative_residual, 100 * v.cv.mean_absolute,
                100 * v.cv.worst, i == best ? "<- chosen" : within_tolerance(v, variants[best]) ? "(in spread)" : "");
  }
  std::printf("  chosen: least CV mean error; spread: CV mean within %.0f%% of it\n", 100 * kVariantTolerance);
}

void print_chosen(const VariantCalibration& v) {
  std::printf("\nChosen variant %s\n", v.used.driver_model.name().c_str());
  std::printf("  %-40s %12s %12s %12s %10s %10s\n", "run", "paper s", "estimate s", "fitted s", "residual", "left out");
  for (std::size_t i = 0; i < v.observations.size(); ++i) {
    const CalibrationObservation& o = v.observations[i];
    std::printf("  %-40s %12.2f %12.2f %12.2f %9.1f%% %9.1f%%\n", o.label.c_str(), o.measured_seconds,
                o.simulated_seconds(), v.fit.predicted_seconds[i], 100 * v.fit.relative_residuals[i],
                100 * v.cv.relative_errors[i]);
  }
  std::printf("  rms relative residual %.1f%%, cross-validated mean %.1f%%, worst %.1f%%\n", 100 * v.fit.rms_relative_residual,
              100 * v.cv.mean_absolute, 100 * v.cv.worst);
}

void write_json(const std::string& path, const nlohmann::ordered_json& j) {
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  std::ofstream out(path);
  out << j.dump(2) << "\n";
  if (!out) throw std::runtime_error(path + ": cannot write");
}

int run_calibrate(const CalibrateOptions& o) {
  ProgressLine progress(!o.quiet);
  const std::vector<PaperRow> rows = load_paper_table(o.table);
  const HostProfile base = find_host_profile(o.base);
  std::vector<HostProfile> variants;
  for (const DriverModel& m : serial_driver_variants(base.driver_model)) variants.push_back(with_driver_model(base, m));
  const std::vector<PaperScene> scenes =
      prepare_paper_scenes(rows, o.visibility, 15, [&](const std::string& what) { progress.update("%s", what.c_str()); });
  const std::vector<TimingCase> cases = calibration_cases(scenes, base, variants);
  progress.update("simulating %zu runs", cases.size());
  const std::vector<TimingOutcome> outcomes = run_timing_study(cases);
  progress.finish();

  const std::size_t n = scenes.size();
  std::vector<VariantCalibration> fitted;
  for (std::size_t v = 0; v < variants.size(); ++v) {
    std::vector<CalibrationObservation> observations;
    for (std::size_t i = 0; i < n; ++i) {
      observations.push_back(observation_from_report(rows[i].label() + " software", rows[i].software_seconds,
                                                     outcomes[i].report, base));
      observations.push_back(observation_from_report(rows[i].label() + " one_pipe", rows[i].one_pipe_seconds,
                                                     outcomes[n + v * n + i].report, variants[v]));
    }
    fitted.push_back(calibrate_variant(variants[v], std::move(observations)));
  }
  const std::size_t best = best_by_cross_validation(fitted);
  const VariantCalibration& chosen = fitted[best];
  write_json(o.out, calibrated_profile(chosen.used, chosen.fit, chosen.observations, o.name, &chosen.cv));
  write_json(o.variants_out, variants_document(fitted, base.name));

  std::printf("rc2000sim calibrate: host profile %s fitted to Table 2 (software and single pipeline)\n", base.name.c_str());
  print_variants(fitted, best);
  print_chosen(chosen);
  std::printf("  wrote %s and %s (%.1f s)\n", o.out.c_str(), o.variants_out.c_str(), progress.seconds());
  return 0;
}

}  // namespace

void add_calibrate_command(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<CalibrateOptions>();
  CLI::App* cmd = app.add_subcommand("calibrate", "Fit the host CPU cost model to Table 2's software and single-pipeline columns");
  cmd->add_option("--table", o->table, "Measured Table 2 columns")->check(CLI::ExistingFile)->capture_default_str();
  cmd->add_option("--base", o->base, "Host profile whose estimates are scaled")->capture_default_str();
  cmd->add_option("--out", o->out, "Calibrated profile of the chosen variant to write")->capture_default_str();
  cmd->add_option("--variants-out", o->variants_out, "Every variant's calibrated profile and cross-validation")
      ->capture_default_str();
  cmd->add_option("--name", o->name, "Name of the calibrated profile")->capture_default_str();
  cmd->add_option("--visibility", o->visibility, "Bit-exact backend that answers visibility once per scene: fixed or fast")
      ->check(CLI::IsMember({"fixed", "fast"}))->capture_default_str();
  cmd->add_flag("--quiet", o->quiet, "No progress output");
  cmd->callback([o, &exit_code] { exit_code = run_calibrate(*o); });
}

}  // namespace rc
