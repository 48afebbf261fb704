#include "host_sw/studies/bench_study.h"

#include <algorithm>
#include <chrono>

#include "pipeline/float_format.h"
#include "host_sw/radiosity/float_visibility.h"

namespace rc {

std::string BenchPoint::label() const { return arith.is_float() ? arith.name() : std::to_string(bits) + " bits"; }

std::vector<BenchPoint> sweep_points(const BenchSpec& o) {
  std::vector<BenchPoint> points{o.base};
  points[0].varied = "base";
  auto vary = [&](const char* what, auto apply) {
    BenchPoint p = o.base;
    p.varied = what;
    apply(p);
    const bool is_base = p.bits == o.base.bits && p.convergence == o.base.convergence &&
                         p.patch_levels == o.base.patch_levels && p.form_factor == o.base.form_factor &&
                         p.arith == o.base.arith;
    if (!is_base) points.push_back(p);
  };
  for (int b : o.widths) vary("bits", [&](BenchPoint& p) { p.bits = b; });
  for (const pipeline::Arithmetic& f : o.formats) vary("arith", [&](BenchPoint& p) { p.arith = f; });
  for (double c : o.convergences) vary("convergence", [&](BenchPoint& p) { p.convergence = c; });
  for (int m : o.patch_levels) vary("patch_levels", [&](BenchPoint& p) { p.patch_levels = m; });
  for (const std::string& name : form_factor_names()) {
    vary("form_factor", [&](BenchPoint& p) { p.form_factor = parse_form_factor_kind(name); });
  }
  return points;
}



namespace {

Reference solve_reference(const BenchSpec& o, int finest) {
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

PointRun solve_point(const BenchSpec& o, const BenchPoint& p, const Reference& ref, int finest) {
  PointRun run;
  run.point = p;
  SceneOptions so = o.scene;
  so.patch_levels = p.patch_levels;
  run.scene = prepare_scene(so).scene;
  run.solver.convergence = p.convergence;
  run.solver.form_factor = p.form_factor;
  const auto t0 = std::chrono::steady_clock::now();
  run.run = record_functional_run(run.scene, run.solver, p.arith.is_float() ? p.arith.name() : o.visibility, p.bits);
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

}  // namespace

BenchResult run_bench_study(const BenchSpec& o, const std::function<void(const std::string&)>& progress) {
  BenchResult b;
  const std::vector<BenchPoint> points = sweep_points(o);
  for (const BenchPoint& p : points) b.finest = std::max(b.finest, p.patch_levels);
  progress("reference solve (" + std::to_string(b.finest) + " patch levels, converged to 1e-6)");
  const auto t0 = std::chrono::steady_clock::now();
  b.reference = solve_reference(o, b.finest);
  b.reference_wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  for (const BenchPoint& p : points) {
    progress("point " + std::to_string(b.runs.size() + 1) + " of " + std::to_string(points.size()) + " (" + p.varied + ")");
    b.runs.push_back(solve_point(o, p, b.reference, b.finest));
  }
  std::vector<TimingCase> cases;
  for (const PointRun& r : b.runs) {
    TimingCase c;
    c.label = r.point.varied;
    c.scene = &r.scene;
    c.solver = r.solver;
    c.recording = &r.run.recording;
    c.board = o.board;
    c.board.bits = r.point.bits;
    if (r.point.arith.is_float()) c.board.float_format = r.point.arith.float_format();
    cases.push_back(c);
  }
  progress("timing study of " + std::to_string(cases.size()) + " points");
  const auto t1 = std::chrono::steady_clock::now();
  b.timing = run_timing_study(cases);
  b.study_wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
  return b;
}

}  // namespace rc
