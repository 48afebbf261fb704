// The picture's fidelity in every run, cheaply (issue 37; docs/radiosity.md, "Fidelity in every
// run"): a uniform sample of the segments a run asked, their answers as the run's own visibility
// gave them (software backend or board), checked against double-precision visibility
// (pipeline::segment_hits_ref, the `float` backend's test, the same own-surface rule).
//
//   DecisionSampler sampler(4096);
//   solver.on_answers(sampler.observer());             // or BoardRunOptions::on_answers
//   solver.run();
//   const Fidelity f = estimate_fidelity(scene, sampler, arith, bits);
//
// The sample: reservoir sampling (Vitter's algorithm R) over every segment whose answer the solver
// uses (SegmentBatch::is_needed), with a fixed seed, so the same run samples the same segments on
// every machine and thread count. Every needed segment of the run is equally likely to be in it; when
// the run asks no more segments than the sample holds, every segment is checked and the share is
// exact.
//
// Each differing segment is explained: the faces that decide it (the pipeline's blockers for a
// shadow double precision does not cast, double's blockers for one the pipeline misses) are classed,
// in this order, as faces whose exact determinant for the segment, edge1 . (d x edge2), is below
// kSmallDeterminantSteps grid steps (fixed point: the product is smaller than what truncation drops,
// so truncation decides; on the meshes measured this explains nearly every difference), mesh
// neighbours of the segment's start or end face (sharing a vertex with it), faces lost on the grid
// (no area at the width), crossings within kNearEndSteps grid steps of an end, or other. The largest
// class names the likely cause in the warning.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "host_sw/radiosity/radiosity.h"
#include "pipeline/arithmetic.h"
#include "scenes/scene.h"

namespace rc {

// One segment the run asked, and what the run answered.
struct SampledSegment {
  Vec3 start, end;
  int source_face = -1, end_face = -1;
  bool answer_blocked = false;
};

class DecisionSampler {
 public:
  // Keeps at most `size` segments (0: none; the run then has no fidelity figure).
  explicit DecisionSampler(std::size_t size, std::uint64_t seed = kDefaultSeed);

  // Offers every needed segment of a step with its answer (blocked.size() == batch.size()).
  void observe(const SegmentBatch& batch, const std::vector<std::uint8_t>& blocked);
  // observe() as the solver's AnswersObserver; the sampler must outlive the run.
  AnswersObserver observer() {
    return [this](const SegmentBatch& b, const std::vector<std::uint8_t>& blocked) { observe(b, blocked); };
  }

  const std::vector<SampledSegment>& sample() const { return sample_; }
  // Needed segments offered so far (the population the sample is drawn from).
  std::uint64_t population() const { return population_; }
  std::size_t capacity() const { return size_; }

  static constexpr std::uint64_t kDefaultSeed = 0x5eed'f1de'1175ULL;

 private:
  std::uint64_t next_random();  // splitmix64: the same sequence everywhere

  std::size_t size_;
  std::uint64_t state_;
  std::uint64_t population_ = 0;
  std::vector<SampledSegment> sample_;
};

// Why differing segments differ: counts by the class of the face that decides them.
struct DifferenceCauses {
  std::uint64_t small_determinant = 0;  // fixed point: its exact determinant is below kSmallDeterminantSteps grid steps
  std::uint64_t neighbour = 0;   // the deciding face shares a vertex with the start or end face
  std::uint64_t lost_face = 0;   // missing shadows: double's blocker has no area at the width
  std::uint64_t near_end = 0;    // the deciding face's plane is crossed within kNearEndSteps grid steps of an end
  std::uint64_t other = 0;
  std::uint64_t total() const { return small_determinant + neighbour + lost_face + near_end + other; }
};

// Grid steps below which a determinant counts as unresolved: det's three truncated products and
// the truncated cross product it is formed from can move it by a few grid steps.
constexpr double kSmallDeterminantSteps = 4;
// Grid steps (2^-bits of the normalised scene; a float format: 2^-M) within which a crossing counts
// as at an end.
constexpr double kNearEndSteps = 4;
// The default share of differing decisions above which a run warns (--fidelity-warn): 1%. The
// paper's own case, the Cornell Box at 15 bits, stays below it (docs/radiosity.md); a share above it
// moves patch radiosity by several percent on the meshes measured there.
constexpr double kDefaultFidelityWarnShare = 0.01;
// The default sample (--fidelity-sample): a 95% interval of at most +-1.6 points at any share.
constexpr std::size_t kDefaultFidelitySample = 4096;

// Throws std::invalid_argument naming --fidelity-sample or --fidelity-warn and its range unless
// 0 <= sample <= kMaxFidelitySample and 0 <= warn_share <= 1 (the library's and Python's check; the
// command line's options carry the same ranges).
constexpr long long kMaxFidelitySample = 10'000'000;
void check_fidelity_options(long long sample, double warn_share);

struct Fidelity {
  std::string arithmetic;           // "fixed:15", "float:5,10"
  std::uint64_t population = 0;     // needed segments the run asked
  std::uint64_t sampled = 0;        // segments checked against double precision
  std::uint64_t false_shadows = 0;  // the run says blocked, double precision clear
  std::uint64_t missing_shadows = 0;  // double precision blocked, the run clear
  // The share of differing decisions, and its 95% interval (Wilson score; exact when every segment
  // was sampled).
  double share = 0, share_low = 0, share_high = 0;
  bool exact = false;  // sampled == population
  DifferenceCauses false_causes, missing_causes;
  std::uint64_t differing() const { return false_shadows + missing_shadows; }
};

// Checks the sample against double precision (on `threads` threads; 0: jobs()) and classes each
// difference. `bits`: the fixed width (ignored for a float format); `t_guard`: the pipeline's guard band
// on t (fixed point), with which the pipeline's own per-face tests of the classes are made.
Fidelity estimate_fidelity(const Scene& scene, const std::vector<SampledSegment>& sample, std::uint64_t population,
                           const pipeline::Arithmetic& arith, int bits, unsigned threads = 0, int t_guard = 0);

// The 95% Wilson score interval of k successes in n trials: {low, high} (n = 0: {0, 1}).
struct ShareInterval {
  double low = 0, high = 1;
};
ShareInterval wilson_interval(std::uint64_t k, std::uint64_t n);

// "26.7% of visibility decisions differ from double precision (95%: 25.3-28.1%; 4,096 of 80,380 segments checked)".
std::string fidelity_line(const Fidelity& f);
// A warning when the share exceeds `warn_share`, naming the likely cause; "" otherwise.
std::string fidelity_warning(const Fidelity& f, double warn_share, int bits);

}  // namespace rc
