// How faithful a pipeline arithmetic's picture is on a workload: for each fixed-point width and
// floating-point format, its own solve (steps, patch radiosity, and a recording of its answers a
// timing study can price) and its error against ONE double-precision solve of the same workload,
// with the visibility decisions that differ counted along that double solve's own trajectory (same
// shooters, same segments). `rc2000sim accuracy` and the design search (design_search.h) use it.
//
// The work, done once however many arithmetics are measured:
//   * the double-precision reference is solved once; at every step its batch is answered in double
//     precision (FloatVisibility) and by every arithmetic (its bit-exact backend, as a shadow), the
//     answers side by side on `jobs` threads, and the needed segments' answers are compared (what
//     ComparingVisibility counts, for all arithmetics in one solve);
//   * each arithmetic's own solve runs on its own, `jobs` of them at a time, each backend on one
//     thread (or more when fewer arithmetics than jobs).
// Every answer is the functional one (make_functional_answer: segments the solver does not need are
// skipped and a repeated shooter's answer reused), which changes no result bit; every figure is
// independent of `jobs` (tests/host_sw/studies/fidelity_test.cpp checks both against the one-solve-
// per-width way).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "host_sw/radiosity/radiosity.h"
#include "host_sw/studies/solution_error.h"
#include "host_sw/studies/timing_study.h"
#include "scenes/scene.h"

namespace rc {

// One arithmetic of the pipeline: a fixed-point width or a floating-point format.
// With `fixes` (segment_fixes.h; fixed point only, their width `bits`), the arithmetic is the pipeline
// with those host-side fixes around it: its own solve applies them (SolverOptions::fixes) and its
// decisions along the reference's trajectory are the fixed answers (FixedSegmentsVisibility).
struct Arithmetic {
  std::string backend = "fast";  // "fast" (fixed point at `bits`) or "float:E,M"
  int bits = 0;                  // fractional bits of fixed point; 0 for a float format
  SegmentFixOptions fixes;       // none by default; else fixes.bits == bits

  static Arithmetic fixed(int bits) { return {"fast", bits, {}}; }
  static Arithmetic floating(const std::string& format) { return {format, 0, {}}; }
  // Fixed point at `bits` with `fixes` (their width set to `bits`).
  static Arithmetic fixed(int bits, SegmentFixOptions fixes);
  bool is_float() const;
  // "fixed:15", "float:5,10"; with fixes "fixed:15+offset:2+rings:1+coordinates:11".
  std::string label() const;
};

// Visibility decisions of one arithmetic against double precision on the segments the solver needs.
struct DecisionCounts {
  std::uint64_t compared = 0;
  std::uint64_t arithmetic_only = 0;  // the arithmetic says blocked, double precision clear
  std::uint64_t double_only = 0;      // double precision says blocked, the arithmetic clear
  std::uint64_t differ() const { return arithmetic_only + double_only; }
  double differ_share() const { return compared ? double(differ()) / double(compared) : 0.0; }
};

struct ArithmeticFidelity {
  Arithmetic arithmetic;
  RecordedRun run;          // its own solve: steps, radiosity, the answers a timing case replays
  SolutionError error;      // of run.result.radiosity against the reference's
  DecisionCounts decisions; // along the reference's trajectory
};

struct FidelityResult {
  SolverResult reference;                 // the double-precision solve
  std::vector<ArithmeticFidelity> rows;   // in the order asked
};

struct FidelityOptions {
  unsigned jobs = 0;  // threads and concurrent solves; 0: jobs() (host_sw/radiosity/jobs.h)
  // What is being done and how much is done ("reference step 12 (double and 8 arithmetics)",
  // "solved fixed:15 (3 of 8)"); called from worker threads, one call at a time.
  std::function<void(const std::string&)> progress;
};

// Throws std::invalid_argument for a bad arithmetic (a width outside 7..31, a malformed format)
// before any work, and rethrows a solve's error.
FidelityResult measure_fidelity(const Scene& scene, const SolverOptions& solver, const std::vector<Arithmetic>& arithmetics,
                                const FidelityOptions& options = {});

// The second part alone: each arithmetic's own solve, `jobs` at a time, in order asked.
std::vector<RecordedRun> solve_arithmetics(const Scene& scene, const SolverOptions& solver, const std::vector<Arithmetic>& arithmetics,
                                           const FidelityOptions& options = {});

// The first part alone: the double-precision solve and, along it, the decisions of every arithmetic.
struct ReferenceDecisions {
  SolverResult reference;
  std::vector<DecisionCounts> decisions;  // one per arithmetic, in order
};
ReferenceDecisions solve_reference(const Scene& scene, const SolverOptions& solver, const std::vector<Arithmetic>& arithmetics,
                                   const FidelityOptions& options = {});

}  // namespace rc
