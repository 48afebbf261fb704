// Progressive-refinement (shooting) radiosity, paper sec 2: shoot from the patch with the most
// unshot power, update every receiver in front of it with form factor x visibility, until the
// largest unshot power falls below (1 - convergence) of the largest initial (emitted) power.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "radiosity/form_factor.h"
#include "radiosity/host_cost.h"
#include "radiosity/visibility.h"
#include "scenes/scene.h"

namespace rc {

struct SolverOptions {
  double convergence = 0.995;  // paper: 99.5%
  int fixed_steps = 0;         // > 0: run exactly this many steps, ignoring convergence
  int max_steps = 10'000'000;  // safety stop; reported as not converged
  int min_steps = 0;           // converging runs: never stop before this many steps (a recording
                               // that timing replays of that many steps will need)
  FormFactorKind form_factor = FormFactorKind::PointToPoint;
  // true: receivers behind the shooter or facing away get no segment. false (paper-faithful):
  // every other patch gets a segment, as the paper's hardware and software tested (they exchange
  // nothing, form factor 0, but their segments are uploaded, tested and paid for).
  bool cull_receivers = true;
};

// Power (radiosity x area), summed over bands. emitted = absorbed + escaping + unshot holds exactly
// up to rounding: every shot either arrives (and is absorbed or reflected into unshot) or escapes.
struct EnergyBalance {
  double emitted = 0;
  double absorbed = 0;
  double escaping = 0;  // shot power not arriving at any patch: open sides, occlusion, F sum < 1
  double unshot = 0;    // still waiting to be shot when the solver stopped
};

struct SolverResult {
  std::vector<Spectrum> radiosity;  // B per patch
  int steps = 0;
  bool converged = false;
  double max_initial_power = 0;
  double max_unshot_power = 0;      // when the solver stopped
  double convergence_reached = 0;   // 1 - max_unshot / max_initial
  EnergyBalance energy;
  std::uint64_t segments = 0;       // visibility segments asked for
  std::uint64_t blocked_segments = 0;   // of the segments whose receiver exchanges energy
  std::uint64_t receivers_skipped = 0;  // behind the shooter or facing away: no segment (when culling)
};

struct StepProgress {
  int step = 0;
  double convergence_reached = 0;
};

class ProgressiveRadiosity {
 public:
  ProgressiveRadiosity(const Scene& scene, VisibilityBackend& visibility, SolverOptions options,
                       HostCostSink* costs = nullptr);
  void on_progress(std::function<void(const StepProgress&)> callback) { progress_ = std::move(callback); }
  SolverResult run();

 private:
  int choose_shooter() const;
  double unshot_power(int patch) const;
  bool done(int steps, double max_unshot) const;
  void shoot(int shooter, SolverResult& result);
  void charge(HostWork work, std::uint64_t count);

  const Scene& scene_;
  VisibilityBackend& visibility_;
  SolverOptions options_;
  HostCostSink* costs_;
  std::function<void(const StepProgress&)> progress_;

  std::vector<Spectrum> radiosity_;
  std::vector<Spectrum> unshot_;
  double initial_max_power_ = 0;
  // Per-step scratch, kept to avoid reallocating every step.
  SegmentBatch batch_;
  std::vector<int> receivers_;
  std::vector<PairGeometry> geometry_;  // shooter-receiver geometry, by receiver
  std::vector<double> form_factors_;
  std::vector<std::uint8_t> blocked_;
};

}  // namespace rc
