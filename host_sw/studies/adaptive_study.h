// `rc2000sim adaptive` as a study (issue 14, paper sec 6): adaptive patches against uniform patches
// at equal patch count. For each uniform level L of the sweep, the uniform run solves the scene's
// faces split into 4^L patches each; the adaptive run starts from `start_levels`, and in `rounds`
// solves splits the patches of steepest radiosity gradient (scenes/adaptive_patches.h) until it has
// exactly as many patches as the uniform run, its last solve at that count. Every solve is bit-exact
// (the pipeline's arithmetic) and its hardware time is simulated by replaying it through the board
// (one timing study); an adaptive run costs all its solves. Errors are measured at the patches of a
// reference (31-bit pipeline visibility, converged to 1e-6, disc form factor, `reference_levels`),
// plus the rendered image's difference. docs/results/adaptive-patches.md.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "host_sw/radiosity/render.h"
#include "scenes/prepare.h"
#include "host_sw/studies/solution_error.h"
#include "host_sw/studies/timing_study.h"

namespace rc {

struct AdaptiveSpec {
  SceneOptions scene;              // faces as made by these options; patch_levels is ignored (swept)
  std::vector<int> levels{1, 2};   // uniform patch levels; each adaptive run matches one's patch count
  int start_levels = 0;            // the adaptive runs' first patches
  int rounds = 5;                  // solves per adaptive run (the last at the target count)
  int reference_levels = 4;        // no patch is split deeper than this (errors are measured there)
  int bits = 15;
  double convergence = 0.995;
  FormFactorKind form_factor = FormFactorKind::Analytic;  // the runs' (the reference's: disc, fixed)
  std::string visibility = "fast";
  BoardRunOptions board;           // the hardware whose time is simulated
  int image_size = 256;
};

struct PatchingSolve {
  Scene scene;
  SolverOptions solver;  // fixed_steps: the steps the functional solve took (the replay runs them)
  RecordedRun run;
  double wall_seconds = 0;
  double simulated_seconds = 0;  // filled by the timing study
};

struct PatchingRun {
  std::string kind;  // "uniform" or "adaptive"
  int level = 0;     // the uniform level whose patch count it has
  std::vector<PatchingSolve> solves;  // uniform: one; adaptive: one per round
  SolutionError error;                // final solution against the reference, at its patches
  double image_difference = 0;
  HdrImage image;
  const PatchingSolve& final_solve() const { return solves.back(); }
  double simulated_seconds() const;   // every solve
  double wall_seconds() const;
};

struct AdaptiveResult {
  Scene reference_scene;
  SolverResult reference;
  HdrImage reference_image;
  double reference_wall_seconds = 0;
  std::vector<PatchingRun> runs;  // per level: uniform, then adaptive
};

// The patch counts of an adaptive run's rounds: from `start` to `target` in `rounds` solves, growing
// geometrically, each count reachable by splits (start + 3k), the last exactly `target`.
std::vector<std::size_t> round_counts(std::size_t start, std::size_t target, int rounds);

// Throws std::invalid_argument for a spec that cannot run (levels above the reference, a start
// level not below every level, fewer than one round). Runs once per process (a timing study).
AdaptiveResult run_adaptive_study(const AdaptiveSpec& spec, const std::function<void(const std::string&)>& progress);

}  // namespace rc
