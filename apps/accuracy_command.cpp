// `rc2000sim accuracy`: what the fixed-point width does to the picture. For each width, the
// radiosity solved with the bit-exact fixed-point visibility is compared with the float solution
// (RMSE and max error of patch radiosity), and the visibility decisions that differ are counted
// along the float solver's own trajectory (same shooters, same segments).
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

#include "apps/cli_options.h"
#include "apps/plot.h"
#include "apps/progress.h"
#include "radiosity/comparing_visibility.h"
#include "radiosity/float_visibility.h"
#include "studies/solution_error.h"
#include "radiosity/visibility_factory.h"

namespace rc {

namespace {

struct AccuracyOptions {
  SceneOptions scene;
  SolverOptions solver;
  std::vector<int> widths{7, 11, 15, 19, 23, 27, 31};
  std::string out_dir = "out/accuracy";
  bool quiet = false;
};

struct WidthResult {
  int bits = 0;
  int steps = 0;
  SolutionError error;
  std::uint64_t segments_compared = 0, fixed_only_blocks = 0, float_only_blocks = 0;
};

WidthResult measure_width(const Scene& scene, const SolverOptions& solver, const SolverResult& reference, int bits) {
  WidthResult r;
  r.bits = bits;
  auto fixed = make_software_visibility("fast", bits);
  const SolverResult solved = ProgressiveRadiosity(scene, *fixed, solver).run();
  r.steps = solved.steps;
  r.error = compare_solutions(solved.radiosity, reference.radiosity);

  FloatVisibility float_answer;
  auto fixed_shadow = make_software_visibility("fast", bits);
  ComparingVisibility compare(float_answer, *fixed_shadow);
  ProgressiveRadiosity(scene, compare, solver).run();
  r.segments_compared = compare.segments_compared();
  r.fixed_only_blocks = compare.shadow_blocks_answer_clear();
  r.float_only_blocks = compare.answer_blocks_shadow_clear();
  return r;
}

void write_csv(const std::string& path, const std::vector<WidthResult>& rows, int float_steps) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error(path + ": cannot open for writing");
  out << "bits,steps,float_steps,rmse,max_abs_error,relative_rmse,relative_max_error,segments,"
         "decisions_differ,fixed_blocks_float_clear,float_blocks_fixed_clear\n";
  for (const WidthResult& r : rows) {
    out << r.bits << ',' << r.steps << ',' << float_steps << ',' << r.error.rmse << ',' << r.error.max_abs << ','
        << r.error.relative_rmse() << ',' << r.error.relative_max() << ',' << r.segments_compared << ','
        << r.fixed_only_blocks + r.float_only_blocks << ',' << r.fixed_only_blocks << ',' << r.float_only_blocks
        << "\n";
  }
}

int run_accuracy(const AccuracyOptions& o) {
  ProgressLine progress(!o.quiet);
  const Scene scene = prepare_scene(o.scene, [&](const std::string& what) { progress.update("%-60s", what.c_str()); }).scene;
  FloatVisibility float_visibility;
  const SolverResult reference = ProgressiveRadiosity(scene, float_visibility, o.solver).run();
  std::vector<WidthResult> rows;
  for (int bits : o.widths) {
    progress.update("width %d bits", bits);
    rows.push_back(measure_width(scene, o.solver, reference, bits));
  }
  progress.finish();
  std::filesystem::create_directories(o.out_dir);
  write_csv(o.out_dir + "/accuracy.csv", rows, reference.steps);
  plot("accuracy.py", o.out_dir + "/accuracy.csv", o.out_dir + "/accuracy.png");

  std::printf("rc2000sim accuracy: %zu faces, %zu patches, float reference %d steps\n", scene.faces.size(),
              scene.patches.size(), reference.steps);
  std::printf("%5s %6s %12s %12s %14s %12s\n", "bits", "steps", "rel. RMSE", "rel. max", "decisions", "differ %");
  for (const WidthResult& r : rows) {
    const std::uint64_t differ = r.fixed_only_blocks + r.float_only_blocks;
    std::printf("%5d %6d %12.3e %12.3e %14llu %12.4f\n", r.bits, r.steps, r.error.relative_rmse(),
                r.error.relative_max(), static_cast<unsigned long long>(differ),
                100.0 * double(differ) / double(r.segments_compared ? r.segments_compared : 1));
  }
  std::printf("errors relative to the mean float radiosity; decisions compared on %llu segments per width\n",
              static_cast<unsigned long long>(rows.empty() ? 0 : rows.front().segments_compared));
  std::printf("wrote %s/accuracy.csv and accuracy.png (%.1f s)\n", o.out_dir.c_str(), progress.seconds());
  return 0;
}

}  // namespace

void add_accuracy_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<AccuracyOptions>();
  auto solver = std::make_shared<SolverCli>();
  CLI::App* cmd = app.add_subcommand("accuracy", "Radiosity error and visibility decisions per fixed-point width, against float");
  add_scene_options(*cmd, options->scene);
  add_solver_options(*cmd, *solver);
  cmd->add_option("--widths", options->widths, "Fractional widths to measure")->check(CLI::Range(7, 31))
      ->delimiter(',')->capture_default_str();
  cmd->add_option("--out", options->out_dir, "Output folder")->capture_default_str();
  cmd->add_flag("--quiet", options->quiet, "No progress output");
  cmd->callback([options, solver, &exit_code] {
    options->solver = solver->resolved();
    exit_code = run_accuracy(*options);
  });
}

}  // namespace rc
