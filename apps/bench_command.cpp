// `rc2000sim bench`: simulator wall time and predicted hardware time against error. Around a base
// point (width, convergence, patch subdivision, form factor) each dimension is varied alone; each
// point is solved once with the bit-exact visibility (timed on the wall clock), then every point's
// hardware time is simulated in one timing study (replayed, docs/board.md), and its radiosity and
// image are compared with a reference: double-precision visibility, converged to 1e-6, disc form
// factor, on the finest patches of the sweep.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>

#include "apps/cli_options.h"
#include "apps/plot.h"
#include "apps/progress.h"
#include "radiosity/float_visibility.h"
#include "radiosity/render.h"
#include "studies/solution_error.h"
#include "studies/timing_study.h"

namespace rc {

namespace {

struct BenchPoint {
  std::string varied;  // which dimension this point varies ("base" for the base point)
  int bits = 15;
  double convergence = 0.995;
  int patch_levels = 2;
  // The disc form factor by default: the paper's point formula's near-field error (docs/radiosity.md)
  // would otherwise swamp every other effect; the sweep still shows the point formula as one point.
  FormFactorKind form_factor = FormFactorKind::Disc;
};

struct BenchOptions {
  SceneOptions scene;  // patch_levels is swept
  BenchPoint base;
  std::vector<int> widths{7, 11, 15, 19, 23, 27, 31};
  std::vector<double> convergences{0.99, 0.995, 0.999, 0.9999};
  std::vector<int> patch_levels{1, 2, 3};
  std::string visibility = "fast";
  BoardRunOptions board;  // the hardware whose time is predicted
  unsigned lanes = 2;     // --lanes, into board.lanes
  std::string out_dir = "out/bench";
  std::string docs_dir;
  bool quiet = false;
};

std::vector<BenchPoint> sweep_points(const BenchOptions& o) {
  std::vector<BenchPoint> points{o.base};
  points[0].varied = "base";
  auto vary = [&](const char* what, auto apply) {
    BenchPoint p = o.base;
    p.varied = what;
    apply(p);
    const bool is_base = p.bits == o.base.bits && p.convergence == o.base.convergence &&
                         p.patch_levels == o.base.patch_levels && p.form_factor == o.base.form_factor;
    if (!is_base) points.push_back(p);
  };
  for (int b : o.widths) vary("bits", [&](BenchPoint& p) { p.bits = b; });
  for (double c : o.convergences) vary("convergence", [&](BenchPoint& p) { p.convergence = c; });
  for (int m : o.patch_levels) vary("patch_levels", [&](BenchPoint& p) { p.patch_levels = m; });
  vary("form_factor", [&](BenchPoint& p) {
    p.form_factor = p.form_factor == FormFactorKind::PointToPoint ? FormFactorKind::Disc : FormFactorKind::PointToPoint;
  });
  return points;
}

struct PointRun {
  BenchPoint point;
  Scene scene;
  SolverOptions solver;
  RecordedRun run;
  double wall_seconds = 0;
  SolutionError error;
  double image_difference = 0;
};

struct Reference {
  Scene scene;
  SolverResult result;
  HdrImage image;
};

Reference solve_reference(const BenchOptions& o, int finest) {
  Reference r;
  SceneOptions so = o.scene;
  so.patch_levels = finest;
  r.scene = prepare_scene(so).scene;
  SolverOptions solver;
  solver.convergence = 1 - 1e-6;
  solver.form_factor = FormFactorKind::Disc;
  FloatVisibility exact;
  r.result = ProgressiveRadiosity(r.scene, exact, solver).run();
  RenderOptions ro;
  ro.width = ro.height = 256;
  r.image = render_radiosity(r.scene, r.result.radiosity, ro);
  return r;
}

PointRun solve_point(const BenchOptions& o, const BenchPoint& p, const Reference& ref, int finest) {
  PointRun run;
  run.point = p;
  SceneOptions so = o.scene;
  so.patch_levels = p.patch_levels;
  run.scene = prepare_scene(so).scene;
  run.solver.convergence = p.convergence;
  run.solver.form_factor = p.form_factor;
  const auto t0 = std::chrono::steady_clock::now();
  run.run = record_functional_run(run.scene, run.solver, o.visibility, p.bits);
  run.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  run.solver.fixed_steps = run.run.result.steps;  // the timing replay runs exactly these steps
  const std::vector<Spectrum> reference =
      coarsen_solution(ref.result.radiosity, ref.scene.faces.size(), finest - p.patch_levels);
  run.error = compare_solutions(run.run.result.radiosity, reference);
  RenderOptions ro;
  ro.width = ro.height = 256;
  run.image_difference = image_difference(render_radiosity(run.scene, run.run.result.radiosity, ro), ref.image);
  return run;
}

void write_csv(const std::string& path, const std::vector<PointRun>& runs, const std::vector<TimingOutcome>& timing) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error(path + ": cannot open for writing");
  out << "varied,bits,convergence,patch_levels,form_factor,patches,steps,wall_seconds,hardware_seconds,"
         "fpga_busy_seconds,relative_rmse,relative_max_error,image_difference\n";
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const PointRun& r = runs[i];
    out << r.point.varied << ',' << r.point.bits << ',' << r.point.convergence << ',' << r.point.patch_levels << ','
        << to_string(r.point.form_factor) << ',' << r.scene.patches.size() << ',' << r.run.result.steps << ','
        << r.wall_seconds << ',' << timing[i].simulated_seconds << ','
        << timing[i].report.time.fpga_busy << ',' << r.error.relative_rmse() << ','
        << r.error.relative_max() << ',' << r.image_difference << "\n";
  }
}

void write_markdown(const std::string& path, const BenchOptions& o, const std::vector<PointRun>& runs,
                    const std::vector<TimingOutcome>& timing, double reference_wall, double study_wall,
                    int finest) {
  std::ofstream md(path);
  if (!md) throw std::runtime_error(path + ": cannot open for writing");
  md << "# Speed against error\n\nGenerated by `build/apps/rc2000sim bench --docs docs/results` (do not edit by hand).\n\n"
        "Each point is solved once with the bit-exact pipeline arithmetic (`" << o.visibility << "` backend; wall time\n"
        "of that functional solve below), its hardware time is predicted by replaying it through the board model ("
     << o.board.device << ", " << o.board.lanes << " lanes, " << (o.board.concurrent ? "concurrent" : "serial")
     << " driver, calibrated host), and its radiosity is compared with a reference: double-precision visibility,\n"
        "converged to 1e-6, disc form factor, "
     << std::to_string(runs.empty() ? 0 : runs.front().scene.faces.size()) << " faces split into 4^" << finest
     << " patches each (coarser points are compared with the reference averaged onto their patches). Errors are\n"
        "relative to the mean reference radiosity; the image difference is the relative RMSE of the linear\n"
        "256 x 256 image.\n\n"
        "| varied | bits | convergence | patches | form factor | steps | wall s | hardware s | rel. RMSE | rel. max | image diff |\n"
        "|---|---:|---:|---:|---|---:|---:|---:|---:|---:|---:|\n";
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const PointRun& r = runs[i];
    char line[512];
    std::snprintf(line, sizeof line, "| %s | %d | %.4f | %zu | %s | %d | %.3f | %.3f | %.2e | %.2e | %.2e |\n",
                  r.point.varied.c_str(), r.point.bits, r.point.convergence, r.scene.patches.size(),
                  to_string(r.point.form_factor).c_str(), r.run.result.steps, r.wall_seconds, timing[i].simulated_seconds,
                  r.error.relative_rmse(), r.error.relative_max(), r.image_difference);
    md << line;
  }
  char tail[512];
  std::snprintf(tail, sizeof tail,
                "\nReference solve %.1f s wall; the timing study of all %zu points %.2f s wall.\n\n"
                "![Pareto](speed-vs-error/pareto.png)\n",
                reference_wall, runs.size(), study_wall);
  md << tail;
}

int run_bench(const BenchOptions& o) {
  ProgressLine progress(!o.quiet);
  const std::vector<BenchPoint> points = sweep_points(o);
  int finest = 0;
  for (const BenchPoint& p : points) finest = std::max(finest, p.patch_levels);
  progress.update("reference solve (%d patch levels, converged to 1e-6)", finest);
  const auto t0 = std::chrono::steady_clock::now();
  const Reference ref = solve_reference(o, finest);
  const double reference_wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  std::vector<PointRun> runs;
  for (const BenchPoint& p : points) {
    progress.update("point %zu of %zu (%s)%-10s", runs.size() + 1, points.size(), p.varied.c_str(), "");
    runs.push_back(solve_point(o, p, ref, finest));
  }
  std::vector<TimingCase> cases;
  for (const PointRun& r : runs) {
    TimingCase c;
    c.label = r.point.varied;
    c.scene = &r.scene;
    c.solver = r.solver;
    c.recording = &r.run.recording;
    c.board = o.board;
    c.board.bits = r.point.bits;
    cases.push_back(c);
  }
  progress.update("timing study of %zu points%-20s", cases.size(), "");
  const auto t1 = std::chrono::steady_clock::now();
  const std::vector<TimingOutcome> timing = run_timing_study(cases);
  const double study_wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
  progress.finish();

  std::filesystem::create_directories(o.out_dir);
  write_csv(o.out_dir + "/bench.csv", runs, timing);
  std::printf("rc2000sim bench: %zu points, reference %zu patches converged to 1e-6 (%.1f s)\n", runs.size(),
              ref.scene.patches.size(), reference_wall);
  std::printf("  %-13s %4s %8s %6s %6s %6s %9s %10s %10s %10s %10s\n", "varied", "bits", "conv", "patch", "ff", "steps",
              "wall s", "hardware s", "rel RMSE", "rel max", "image");
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const PointRun& r = runs[i];
    std::printf("  %-13s %4d %8.4f %6zu %6s %6d %9.3f %10.3f %10.2e %10.2e %10.2e\n", r.point.varied.c_str(), r.point.bits,
                r.point.convergence, r.scene.patches.size(), to_string(r.point.form_factor).c_str(), r.run.result.steps,
                r.wall_seconds, timing[i].simulated_seconds, r.error.relative_rmse(), r.error.relative_max(),
                r.image_difference);
  }
  const std::string pictures = o.docs_dir.empty() ? o.out_dir : o.docs_dir + "/speed-vs-error";
  std::filesystem::create_directories(pictures);
  plot("bench.py", o.out_dir + "/bench.csv", pictures + "/pareto.png");
  if (!o.docs_dir.empty()) {
    write_markdown(o.docs_dir + "/speed-vs-error.md", o, runs, timing, reference_wall, study_wall, finest);
    std::filesystem::copy_file(o.out_dir + "/bench.csv", pictures + "/bench.csv",
                               std::filesystem::copy_options::overwrite_existing);
  }
  std::printf("  timing study %.2f s; wrote %s/bench.csv and %s/pareto.png (%.1f s)\n", study_wall, o.out_dir.c_str(),
              pictures.c_str(), progress.seconds());
  return 0;
}

}  // namespace

void add_bench_command(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<BenchOptions>();
  auto base_ff = std::make_shared<std::string>("disc");
  o->board.concurrent = true;
  o->board.host = "athlon-mp-2600-calibrated";
  CLI::App* cmd = app.add_subcommand("bench", "Simulator wall time and predicted hardware time against radiosity error");
  add_scene_options(*cmd, o->scene);
  cmd->add_option("--bits", o->base.bits, "Base point: fractional bits")->check(CLI::Range(7, 31))->capture_default_str();
  cmd->add_option("--convergence", o->base.convergence, "Base point: convergence")->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  cmd->add_option("--base-patch-levels", o->base.patch_levels, "Base point: patch levels")->check(CLI::Range(0, 6))
      ->capture_default_str();
  cmd->add_option("--form-factor", *base_ff, "Base point: form factor")->check(CLI::IsMember({"point", "disc"}))
      ->capture_default_str();
  cmd->add_option("--widths", o->widths, "Widths to sweep")->check(CLI::Range(7, 31))->delimiter(',')->capture_default_str();
  cmd->add_option("--convergences", o->convergences, "Convergence thresholds to sweep")->check(CLI::Range(0.0, 1.0))
      ->delimiter(',')->capture_default_str();
  cmd->add_option("--sweep-patch-levels", o->patch_levels, "Patch levels to sweep")->check(CLI::Range(0, 6))
      ->delimiter(',')->capture_default_str();
  cmd->add_option("--visibility", o->visibility, "Bit-exact backend for the points: fixed or fast")
      ->check(CLI::IsMember({"fixed", "fast"}))->capture_default_str();
  cmd->add_option("--device", o->board.device, "Board whose time is predicted")->capture_default_str();
  cmd->add_option("--lanes", o->lanes, "Lanes of that board")->check(CLI::Range(1, 64))->capture_default_str();
  cmd->add_option("--host", o->board.host, "Host profile")->capture_default_str();
  cmd->add_option("--out", o->out_dir, "Output folder")->capture_default_str();
  cmd->add_option("--docs", o->docs_dir, "Also write speed-vs-error.md and its plot here (e.g. docs/results)");
  cmd->add_flag("--quiet", o->quiet, "No progress output");
  cmd->callback([o, base_ff, &exit_code] {
    o->base.form_factor = parse_form_factor_kind(*base_ff);
    o->board.lanes = o->lanes;
    exit_code = run_bench(*o);
  });
}

}  // namespace rc
