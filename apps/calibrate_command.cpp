// `rc2000sim calibrate`: fits the host CPU cost model to the paper's Table 2 software and
// single-pipeline columns (and nothing else), and writes the calibrated host profile.
#include <cstdio>
#include <stdexcept>
#include <memory>

#include "apps/cli_options.h"
#include "apps/outputs.h"
#include "apps/report.h"
#include "profiles/profile_document.h"
#include "host_sw/studies/paper_workload.h"
#include "apps/progress.h"
#include "host_sw/studies/calibration_json.h"
#include "host_sw/studies/calibration_variants_json.h"
#include "host_sw/studies/paper_calibration.h"
#include "host_sw/visibility/visibility_factory.h"

namespace rc {

namespace {

struct CalibrateOptions {
  std::string table = default_paper_table_path();
  std::string base = "athlon-mp-2600";
  std::string out = profiles::default_config_dir() + "/hosts/athlon-mp-2600-calibrated.json";
  std::string variants_out = default_variants_path();
  std::string name = "athlon-mp-2600-calibrated";
  std::string visibility = "fast";
  bool quiet = false;
};

void print_variants(const std::vector<VariantCalibration>& variants, std::size_t best) {
  std::printf("\nDriver-model variants (docs/calibration.md): fit to all %zu runs, and leave-one-out cross-validation\n",
              variants[best].observations.size());
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

int run_calibrate(const CalibrateOptions& o) {
  Outputs outputs;
  outputs.expect(o.out);  // before the fit's seconds of work
  outputs.expect(o.variants_out);
  ProgressLine progress(!o.quiet);
  const std::vector<PaperRow> rows = load_paper_table(o.table);
  const HostProfile base = find_host_profile(o.base);
  const std::vector<PaperScene> scenes =
      prepare_paper_scenes(rows, o.visibility, 15, [&](const std::string& what) { progress.update("%s", what.c_str()); });
  progress.update("simulating the variants' runs");
  const PaperCalibration calibration = calibrate_on_paper(scenes, base);
  progress.finish();
  const std::vector<VariantCalibration>& fitted = calibration.variants;
  const std::size_t best = calibration.chosen;
  const VariantCalibration& chosen = fitted[best];
  const std::string problem = fit_problem(chosen.fit, chosen.observations);
  if (!problem.empty()) {
    print_variants(fitted, best);  // what was fitted, before the refusal says why it is not written
    print_chosen(chosen);
    throw std::invalid_argument(o.table + ": variant " + chosen.used.driver_model.name() + ": " + problem);
  }
  outputs.add(o.out, pretty_json(calibrated_profile(chosen.used, chosen.fit, chosen.observations, o.name, &chosen.cv)));
  outputs.add(o.variants_out, pretty_json(variants_document(fitted, base.name)));
  outputs.write();

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
  cmd->add_option("--out", o->out, "Calibrated profile of the chosen variant to write")
      ->check(output_path())->capture_default_str();
  cmd->add_option("--variants-out", o->variants_out, "Every variant's calibrated profile and cross-validation")
      ->check(output_path())
      ->capture_default_str();
  cmd->add_option("--name", o->name, "Name of the calibrated profile")->capture_default_str();
  cmd->add_option("--visibility", o->visibility, "Bit-exact backend that answers visibility once per scene: fixed or fast")
      ->check(CLI::IsMember(choice_names<BitExactVisibility>()))->capture_default_str();
  cmd->add_flag("--quiet", o->quiet, "No progress output");
  add_jobs_option(*cmd, "the scenes solved side by side, the timing study's processes");
  cmd->callback([o, cmd, &exit_code] {
    // Defaults in the config folder chosen at run time (--configs, after these defaults were made).
    if (!given(*cmd, "--table")) o->table = default_paper_table_path();
    if (!given(*cmd, "--out")) o->out = profiles::default_config_dir() + "/hosts/athlon-mp-2600-calibrated.json";
    if (!given(*cmd, "--variants-out")) o->variants_out = default_variants_path();
    if (o->name.empty()) refuse_option("--name", "must not be empty (it names the calibrated profile)");
    if (o->out == o->variants_out) refuse_option("--variants-out", "is the same file as --out");
    exit_code = run_guarded("calibrate", listed({o->out, o->variants_out}), [&] { return run_calibrate(*o); });
  });
}

}  // namespace rc
