// Progressive-refinement (shooting) radiosity, paper sec 2: shoot from the patch with the most
// unshot power, update every receiver in front of it with form factor x visibility, until the
// largest unshot power falls below (1 - convergence) of the largest initial (emitted) power.
//
// Guarded (docs/radiosity.md, "Guards"): a solve whose unshot power exceeds the emitted power, or
// whose radiosity or unshot power is not finite, stops with SolveDiverged, whose message says at
// which step, which patches and form factor were involved, and what to try.
#pragma once

#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "radiosity/form_factor.h"
#include "radiosity/host_cost.h"
#include "radiosity/visibility.h"
#include "scenes/scene.h"

namespace rc {

// The solve has created energy (more power waiting to be shot than the lights ever emitted) or
// produced a value that is not finite. what() names the step, the patches and the largest form
// factor of that step, and what to try (--form-factor disc, smaller patches, fixing a folded quad).
class SolveDiverged : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

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
  // One pass over the patches: the next shooter (most unshot power, lowest index on ties) and the
  // total unshot power, which the energy guard checks.
  struct UnshotScan {
    int shooter = 0;
    double total = 0;
  };
  UnshotScan scan_unshot() const;
  double unshot_power(int patch) const;
  // Throws SolveDiverged when the total unshot power after `step` steps is not finite or exceeds
  // the emitted power beyond the sums' rounding; `shooter` shot last.
  void check_energy(int step, int shooter, double total_unshot, const SolverResult& result) const;
  void check_radiosity_finite(int steps) const;
  std::string last_step_diagnosis(int shooter) const;
  std::string patch_name(int patch) const;
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
  double energy_limit_ = 0;  // the emitted power plus the rounding of the sums that measure it
  Spectrum last_shot_;       // what the last step shot (for SolveDiverged's diagnosis)
  // Per-step scratch, kept to avoid reallocating every step.
  SegmentBatch batch_;
  std::vector<int> receivers_;
  std::vector<PairGeometry> geometry_;  // shooter-receiver geometry, by receiver
  std::vector<double> form_factors_;
  std::vector<std::uint8_t> blocked_;
};

}  // namespace rc
