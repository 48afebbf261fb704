// `rc2000sim bench` as a study: around a base point (width, convergence, patch subdivision, form
// factor) each dimension is varied alone; each point is solved once with the bit-exact visibility
// (timed on the wall clock), every point's hardware time is simulated in one timing study, and its
// radiosity and image are compared with a reference (double-precision visibility, converged to
// 1e-6, disc form factor, the finest patches of the sweep). The command writes the results.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "host_sw/radiosity/render.h"
#include "pipeline/arithmetic.h"
#include "scenes/prepare.h"
#include "host_sw/studies/solution_error.h"
#include "host_sw/studies/timing_study.h"

namespace rc {

struct BenchPoint {
  std::string varied;  // which dimension this point varies ("base" for the base point)
  int bits = 15;
  double convergence = 0.995;
  int patch_levels = 2;
  // The analytic form factor by default (bench explores our design space, it does not replicate the
  // paper): the paper's point formula's near-field error (docs/radiosity.md) would otherwise swamp
  // every other effect; the sweep still shows the point and disc formulas as one point each.
  FormFactorKind form_factor = FormFactorKind::Analytic;
  pipeline::Arithmetic arith;  // fixed point (at `bits`), or a float format (bits unused)
  std::string label() const;    // "15 bits", "float:5,10"
};

struct BenchSpec {
  SceneOptions scene;  // patch_levels is swept
  BenchPoint base;
  std::vector<int> widths{7, 11, 15, 19, 23, 27, 31};
  std::vector<double> convergences{0.99, 0.995, 0.999, 0.9999};
  std::vector<int> patch_levels{1, 2, 3};
  // Float pipelines beside the fixed widths (paper sec 6), each on the board's float lanes.
  std::vector<pipeline::Arithmetic> formats{pipeline::Arithmetic(pipeline::FloatFormat(5, 10)),
                                            pipeline::Arithmetic(pipeline::FloatFormat(8, 23))};
  std::string visibility = "fast";
  BoardRunOptions board;  // the hardware whose time is predicted
};

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

struct BenchResult {
  Reference reference;
  double reference_wall_seconds = 0;
  int finest = 0;                      // patch levels of the reference
  std::vector<PointRun> runs;          // sweep_points order
  std::vector<TimingOutcome> timing;   // one per run
  double study_wall_seconds = 0;
};

// The base point, then each dimension varied alone (points equal to the base are left out).
std::vector<BenchPoint> sweep_points(const BenchSpec& spec);

// Runs the whole study (once per process: it runs the timing study).
BenchResult run_bench_study(const BenchSpec& spec, const std::function<void(const std::string&)>& progress);

}  // namespace rc
