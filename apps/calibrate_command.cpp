// `rc2000sim calibrate`: fits the host CPU cost model to the paper's Table 2 software and
// single-pipeline columns (and nothing else), and writes the calibrated host profile.
#include <cstdio>
#include <fstream>
#include <memory>

#include "apps/cli_options.h"
#include "apps/paper_workload.h"
#include "apps/progress.h"
#include "host_sw/calibration.h"

namespace rc {

namespace {

struct CalibrateOptions {
  std::string table = default_paper_table_path();
  std::string base = "athlon-mp-2600";
  std::string out = std::string(RC_SOURCE_DIR) + "/configs/hosts/athlon-mp-2600-calibrated.json";
  std::string name = "athlon-mp-2600-calibrated";
  std::string visibility = "fast";
  int bits = 15;
  bool quiet = false;
};

std::vector<TimingCase> calibration_cases(const std::vector<PaperScene>& scenes, const std::string& host) {
  std::vector<TimingCase> cases;
  for (const PaperScene& s : scenes) {
    cases.push_back(paper_timing_case(s, PaperImplementation::Software, host));
    cases.push_back(paper_timing_case(s, PaperImplementation::OnePipe, host));
  }
  return cases;
}

int run_calibrate(const CalibrateOptions& o) {
  ProgressLine progress(!o.quiet);
  const std::vector<PaperRow> rows = load_paper_table(o.table);
  const HostProfile base = find_host_profile(o.base);
  const std::vector<PaperScene> scenes =
      prepare_paper_scenes(rows, o.visibility, 15, [&](const std::string& what) { progress.update("%s", what.c_str()); });
  progress.update("simulating %zu runs", 2 * scenes.size());
  const std::vector<TimingOutcome> outcomes = run_timing_study(calibration_cases(scenes, o.base));
  progress.finish();

  std::vector<CalibrationObservation> observations;
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    observations.push_back(observation_from_report(outcomes[2 * i].label, rows[i].software_seconds, outcomes[2 * i].report, base));
    observations.push_back(observation_from_report(outcomes[2 * i + 1].label, rows[i].one_pipe_seconds, outcomes[2 * i + 1].report, base));
  }
  const CalibrationFit fit = fit_calibration(observations);
  std::ofstream(o.out) << calibrated_profile(base, fit, observations, o.name).dump(2) << "\n";

  std::printf("rc2000sim calibrate: host profile %s fitted to Table 2 (software and single pipeline)\n", base.name.c_str());
  std::printf("  %-16s %s\n", "group", "factor on the estimate");
  for (int g = 0; g < kCostGroups; ++g) std::printf("  %-16s %.4g\n", to_string(CostGroup(g)).c_str(), fit.scale[g]);
  std::printf("  %-24s %12s %12s %12s %10s\n", "run", "paper s", "estimate s", "fitted s", "residual");
  for (std::size_t i = 0; i < observations.size(); ++i) {
    std::printf("  %-24s %12.2f %12.2f %12.2f %9.1f%%\n", observations[i].label.c_str(), observations[i].measured_seconds,
                observations[i].simulated_seconds(), fit.predicted_seconds[i], 100 * fit.relative_residuals[i]);
  }
  std::printf("  rms relative residual %.1f%%\n  wrote %s (%.1f s)\n", 100 * fit.rms_relative_residual, o.out.c_str(),
              progress.seconds());
  return 0;
}

}  // namespace

void add_calibrate_command(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<CalibrateOptions>();
  CLI::App* cmd = app.add_subcommand("calibrate", "Fit the host CPU cost model to Table 2's software and single-pipeline columns");
  cmd->add_option("--table", o->table, "Measured Table 2 columns")->check(CLI::ExistingFile)->capture_default_str();
  cmd->add_option("--base", o->base, "Host profile whose estimates are scaled")->capture_default_str();
  cmd->add_option("--out", o->out, "Calibrated profile to write")->capture_default_str();
  cmd->add_option("--name", o->name, "Name of the calibrated profile")->capture_default_str();
  cmd->add_option("--visibility", o->visibility, "Bit-exact backend that answers visibility once per scene: fixed or fast")
      ->check(CLI::IsMember({"fixed", "fast"}))->capture_default_str();
  cmd->add_flag("--quiet", o->quiet, "No progress output");
  cmd->callback([o, &exit_code] { exit_code = run_calibrate(*o); });
}

}  // namespace rc
