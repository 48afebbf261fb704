#include "host_sw/studies/adaptive_study.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "host_sw/visibility/visibility_factory.h"
#include "scenes/adaptive_patches.h"

namespace rc {

namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

void check(const AdaptiveSpec& s) {
  if (s.levels.empty()) throw std::invalid_argument("adaptive: no patch levels to compare");
  if (s.rounds < 2) throw std::invalid_argument("adaptive: --rounds must be at least 2 (a first solve to find the gradients, then one at the target count)");
  for (int level : s.levels) {
    if (level > s.reference_levels) {
      throw std::invalid_argument("adaptive: patch level " + std::to_string(level) + " is finer than the reference's " +
                                  std::to_string(s.reference_levels));
    }
    if (level <= s.start_levels) {
      throw std::invalid_argument("adaptive: patch level " + std::to_string(level) +
                                  " is not above the adaptive runs' start level " + std::to_string(s.start_levels));
    }
  }
}

Scene scene_at(const AdaptiveSpec& s, int levels) {
  SceneOptions o = s.scene;
  o.patch_levels = levels;
  o.patch_size = 0;
  return prepare_scene(o).scene;
}

SolverOptions point_solver(const AdaptiveSpec& s) {
  SolverOptions o;
  o.convergence = s.convergence;
  o.form_factor = s.form_factor;
  return o;
}

PatchingSolve solve_adaptive(const AdaptiveSpec& s, Scene scene) {
  PatchingSolve p;
  p.scene = std::move(scene);
  p.solver = point_solver(s);
  const auto t0 = Clock::now();
  p.run = record_functional_run(p.scene, p.solver, s.visibility, s.bits);
  p.wall_seconds = since(t0);
  p.solver.fixed_steps = p.run.result.steps;
  return p;
}

void measure(const AdaptiveSpec& s, const AdaptiveResult& ref, PatchingRun& r) {
  const PatchingSolve& last = r.final_solve();
  r.error = compare_solutions(sample_at_finer(last.scene, last.run.result.radiosity, ref.reference_scene),
                              ref.reference.radiosity);
  RenderOptions ro;
  ro.width = ro.height = s.image_size;
  r.image = render_radiosity(last.scene, last.run.result.radiosity, ro);
  r.image_difference = image_difference(r.image, ref.reference_image);
}

PatchingRun adaptive_run(const AdaptiveSpec& s, int level, const std::function<void(const std::string&)>& progress) {
  PatchingRun r;
  r.kind = "adaptive";
  r.level = level;
  Scene scene = scene_at(s, s.start_levels);
  const std::size_t target = scene_at(s, level).patches.size();
  const std::vector<std::size_t> counts = round_counts(scene.patches.size(), target, s.rounds);
  for (std::size_t round = 0; round < counts.size(); ++round) {
    if (round > 0) {
      const PatchingSolve& before = r.solves.back();
      const std::vector<double> g = radiosity_gradients(before.scene, before.run.result.radiosity);
      scene = before.scene;
      scene.patches = split_steepest(before.scene, g, (counts[round] - before.scene.patches.size()) / 3, s.reference_levels);
      if (scene.patches.size() != counts[round]) {
        throw std::runtime_error("adaptive: round " + std::to_string(round + 1) + " reached " +
                                 std::to_string(scene.patches.size()) + " patches, not " + std::to_string(counts[round]) +
                                 " (every steep patch is already " + std::to_string(s.reference_levels) + " levels deep)");
      }
    }
    progress("adaptive to level " + std::to_string(level) + ": round " + std::to_string(round + 1) + " of " +
             std::to_string(counts.size()) + ", " + std::to_string(scene.patches.size()) + " patches");
    r.solves.push_back(solve_adaptive(s, scene));
  }
  return r;
}

}  // namespace

double PatchingRun::simulated_seconds() const {
  double t = 0;
  for (const PatchingSolve& p : solves) t += p.simulated_seconds;
  return t;
}

double PatchingRun::wall_seconds() const {
  double t = 0;
  for (const PatchingSolve& p : solves) t += p.wall_seconds;
  return t;
}

std::vector<std::size_t> round_counts(std::size_t start, std::size_t target, int rounds) {
  if (rounds < 2 || target < start || (target - start) % 3 != 0)
    throw std::invalid_argument("round_counts: cannot go from " + std::to_string(start) + " to " + std::to_string(target) +
                                " patches by splits in " + std::to_string(rounds) + " round(s)");
  std::vector<std::size_t> counts{start};
  for (int r = 1; r < rounds; ++r) {
    const double x = static_cast<double>(start) * std::pow(static_cast<double>(target) / start, double(r) / (rounds - 1));
    std::size_t n = start + 3 * static_cast<std::size_t>(std::llround((x - static_cast<double>(start)) / 3));
    n = std::min(std::max(n, counts.back()), target);
    counts.push_back(n);
  }
  counts.back() = target;
  return counts;
}

AdaptiveResult run_adaptive_study(const AdaptiveSpec& s, const std::function<void(const std::string&)>& progress) {
  check(s);
  AdaptiveResult result;
  progress("reference solve (" + std::to_string(s.reference_levels) + " patch levels, converged to 1e-6)");
  // The 31-bit pipeline arithmetic, culled (bit-exact, many times faster than double-precision
  // visibility at these sizes); at 31 bits its answers differ from double precision's on a
  // negligible share of segments (docs/results/accuracy.md).
  const auto t0 = Clock::now();
  result.reference_scene = scene_at(s, s.reference_levels);
  SolverOptions exact_solver;
  exact_solver.convergence = 1 - 1e-6;
  exact_solver.form_factor = FormFactorKind::Disc;
  const std::unique_ptr<VisibilityBackend> exact = make_software_visibility("fast", 31);
  result.reference = ProgressiveRadiosity(result.reference_scene, *exact, exact_solver).run();
  RenderOptions ro;
  ro.width = ro.height = s.image_size;
  result.reference_image = render_radiosity(result.reference_scene, result.reference.radiosity, ro);
  result.reference_wall_seconds = since(t0);
  for (int level : s.levels) {
    progress("uniform level " + std::to_string(level));
    PatchingRun uniform;
    uniform.kind = "uniform";
    uniform.level = level;
    uniform.solves.push_back(solve_adaptive(s, scene_at(s, level)));
    result.runs.push_back(std::move(uniform));
    result.runs.push_back(adaptive_run(s, level, progress));
  }
  std::vector<TimingCase> cases;
  for (PatchingRun& r : result.runs) {
    measure(s, result, r);
    for (const PatchingSolve& p : r.solves) {
      TimingCase c;
      c.label = r.kind + " level " + std::to_string(r.level) + ", " + std::to_string(p.scene.patches.size()) + " patches";
      c.scene = &p.scene;
      c.solver = p.solver;
      c.recording = &p.run.recording;
      c.board = s.board;
      c.board.bits = s.bits;
      cases.push_back(c);
    }
  }
  progress("timing study of " + std::to_string(cases.size()) + " solves");
  const std::vector<TimingOutcome> timing = run_timing_study(cases);
  std::size_t next = 0;
  for (PatchingRun& r : result.runs)
    for (PatchingSolve& p : r.solves) p.simulated_seconds = timing[next++].simulated_seconds;
  return result;
}

}  // namespace rc
