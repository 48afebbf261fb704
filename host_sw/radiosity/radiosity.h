// Progressive-refinement (shooting) radiosity, paper sec 2: shoot from the patch with the most
// unshot power, update every receiver in front of it with form factor x visibility, until the
// largest unshot power falls below (1 - convergence) of the largest initial (emitted) power.
//
// Guarded (docs/radiosity.md, "Guards"): a solve whose unshot power exceeds the emitted power, whose
// absorbed power exceeds the emitted power or whose escaping power goes negative (energy created),
// or whose radiosity or unshot power is not finite, stops with SolveDiverged, whose message says at
// which step, which patches and form factor were involved, and what to try.
//
// Pairs that never exchange energy (docs/radiosity.md, step 2): a receiver behind the shooter or
// facing away, a receiver on a face of the shooter's sheet (scenes/sheets.h), and a receiver whose
// centre coincides with the shooter's (kCoincidentDistance).
#pragma once

#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "host_sw/radiosity/form_factor.h"
#include "host_sw/radiosity/host_cost.h"
#include "host_sw/radiosity/receiver_sweep.h"
#include "host_sw/radiosity/segment_fixes.h"
#include "host_sw/radiosity/visibility.h"
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
  // The analytic rule never creates energy (docs/radiosity.md, step 4); the paper's workloads set
  // PointToPoint explicitly.
  FormFactorKind form_factor = FormFactorKind::Analytic;
  // true: receivers behind the shooter or facing away get no segment. false (paper-faithful):
  // every other patch gets a segment, as the paper's hardware and software tested (they exchange
  // nothing, form factor 0, but their segments are uploaded, tested and paid for).
  bool cull_receivers = true;
  // Host-side fixes for fixed-point self-shadowing (segment_fixes.h; none by default).
  SegmentFixOptions fixes;
};

// Power (radiosity x area), summed over bands. emitted = absorbed + escaping + unshot holds exactly
// up to rounding: every shot either arrives (and is absorbed or reflected into unshot) or escapes.
struct EnergyBalance {
  double emitted = 0;
  double absorbed = 0;
  double escaping = 0;  // shot power not arriving at any patch: open sides, occlusion, F sum < 1
  double unshot = 0;    // still waiting to be shot when the solver stopped
};

// Per step, S = sum over the receivers that got energy (needed, unblocked) of F_js A_j / A_s: the
// share of the shot power that arrived. S > 1 creates energy. The analytic rule scales such a step's
// deliveries by 1/S (normalised); point and disc leave them (the run warns: form_factor_sum_warning).
struct FormFactorSums {
  std::uint64_t steps_above_one = 0;  // steps with S > 1 (analytic: the steps normalised)
  double largest = 0;                 // the largest S of any step
  int largest_step = 0;               // its step (1-based) and shooter; 0 and -1 before any step
  int largest_shooter = -1;
  bool normalised = false;            // the analytic rule: steps above one were scaled by 1/S
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
  // SolverOptions::fixes: the host's re-tests (neighbour rule) and the segments they cleared.
  std::uint64_t fix_tests = 0;
  std::uint64_t fix_cleared = 0;
  FormFactorSums form_factor_sums;
  // Emission was scaled by 2^emission_exponent for the solve (0: not scaled) so that no power is
  // subnormal; radiosity and energies are reported unscaled (kSmallestUnscaledEmission).
  int emission_exponent = 0;
  // The run stopped before the steps it was asked for (or before converging) because the largest
  // unshot power fell below kSmallestShotPower: nothing left to shoot is a normal number
  // (docs/radiosity.md, Guards). steps says where it stopped.
  bool exhausted = false;
  // With emission_exponent != 0: the radiosity in the solve's units (emission x 2^emission_exponent),
  // where no value underflows; empty otherwise. The picture is drawn from it (render is scale-free).
  std::vector<Spectrum> radiosity_solved;
  // Per patch, the power it shot in all (solve units) and the share S of its shots that arrived
  // (after any normalisation; the same at every shot of one shooter): what the energy
  // plausibility check (energy_plausibility.h) compares with the scene's geometry.
  std::vector<double> shot_power_by_patch;
  std::vector<double> delivered_share_by_patch;
};

// A scene whose largest emission (any band of any emitting material) is below this is solved with
// its emission scaled by an exact power of two into [0.5, 1) and its radiosity scaled back: below
// about 1e-308 powers and the convergence threshold are subnormal, lose their digits, and the solve
// never converges. Powers of two scale exactly in binary floating point, and scenes above this
// limit are not scaled at all, so they stay bit-identical. 2^-256 (about 8.6e-78) leaves 2^750 of
// headroom below it for the products of form factors, reflectances and the convergence target.
constexpr double kSmallestUnscaledEmission = 0x1p-256;

// The solve stops (SolverResult::exhausted) once the largest unshot power, in the solve's units, is
// below this: 2^-960, 2^62 above the smallest normal double. A shot below it splits into deliveries
// (times form factors, reflectances, over areas) that are subnormal numbers, with fewer than 53
// bits and absolute rounding of 2^-1074 each, where the energy bookkeeping no longer holds to its
// relative rounding (the analytic rule's delivery check reported such a step as an internal error).
// Emission is at least 2^-256 in the solve's units (kSmallestUnscaledEmission), so everything left
// is below 2^-700 of the emitted power times the patch's area: no output it could change is printed.
constexpr double kSmallestShotPower = 0x1p-960;

// Centres closer than this times the square root of the larger patch area coincide: the pair never
// exchanges energy. The back face of a two-sided surface puts its patch centres about 1e-16 from the
// front's (rounding of the same vertices in another order), where the cosines are arbitrary and the
// point form factor reaches 1e28; two distinct patches this close (a millionth of their size) have
// no meaningful form factor under any rule. Relative to the patch size, so the rule does not depend
// on the scene's scale.
constexpr double kCoincidentDistance = 1e-6;

// "patch 12 (face 3, surface 'floor')".
std::string describe_patch(const Scene& scene, int patch);

// One warning for a point or disc solve with steps whose form-factor sum S exceeded 1: how many, and
// the worst (step, shooter, S). "" for the analytic rule (it normalises) and when no step exceeded 1.
std::string form_factor_sum_warning(const Scene& scene, const SolverResult& result, FormFactorKind kind);

struct StepProgress {
  int step = 0;
  double convergence_reached = 0;
};

// What a step asked and the answers the solver uses (blocked: one flag per segment of batch), seen
// after collect() and after SolverOptions::fixes (the batch as the solver made it, before any offset;
// the answers after the neighbour rule), before the solver uses them: a fidelity sample (host_sw/visibility/
// decision_sample.h) watches the run's own decisions through it, whoever gives them.
using AnswersObserver = std::function<void(const SegmentBatch& batch, const std::vector<std::uint8_t>& blocked)>;

// One pass over n >= 1 values: the index of the first largest one (ignoring NaNs after the
// first value, as `if (p > best)` does), and whether their sum in index order (power[0] + power[1]
// + ...) is surely <= limit, known without forming that sum (false when unsure).
struct PowerScan {
  std::size_t first_maximum = 0;
  bool within_limit = false;
};
PowerScan scan_powers(const double* power, std::size_t n, double limit);

class ProgressiveRadiosity {
 public:
  ProgressiveRadiosity(const Scene& scene, VisibilityBackend& visibility, SolverOptions options,
                       HostCostSink* costs = nullptr);
  void on_progress(std::function<void(const StepProgress&)> callback) { progress_ = std::move(callback); }
  void on_answers(AnswersObserver observer) { answers_ = std::move(observer); }
  SolverResult run();

 private:
  // One pass over the patches: the next shooter (most unshot power, lowest index on ties) and
  // whether the total unshot power, summed in index order, is surely within the energy guard's
  // limit (radiosity.cpp, scan_unshot); when it is not, unshot_total() sums it for the guard.
  struct UnshotScan {
    int shooter = 0;
    bool within_limit = false;
  };
  UnshotScan scan_unshot() const;
  double unshot_total() const;  // the unshot power summed in index order
  double unshot_power(int patch) const;  // unshot x area, kept up to date by set_unshot
  void set_unshot(int patch, const Spectrum& unshot);
  // Throws SolveDiverged when the total unshot power after `step` steps is not finite or exceeds
  // the emitted power beyond the sums' rounding; `shooter` shot last.
  void check_energy(int step, int shooter, double total_unshot, const SolverResult& result) const;
  // Throws SolveDiverged when the absorbed power exceeds the emitted power or the escaping power is
  // negative beyond the sums' rounding (energy created, whatever the reflectances).
  void check_balance(int step, int shooter, const SolverResult& result) const;
  // The step's receivers from sweep_ (pairs that never exchange: sheet, coincident centres, or the
  // cosines, PairGeometry::exchanges): culled to those that exchange, or every other patch.
  void select_exchanging_receivers(int shooter, SolverResult& result);
  void select_every_receiver(int shooter);
  // The share of the shot power the step delivers (S) and the factor its deliveries take.
  double delivered_share(const Patch& shooter) const;
  double unscaled(double power) const { return std::ldexp(power, -emission_exponent_); }
  void check_radiosity_finite(int steps) const;
  std::string last_step_diagnosis(int shooter) const;
  std::string patch_name(int patch) const { return describe_patch(scene_, patch); }
  bool done(int steps, double max_unshot) const;
  void shoot(int shooter, SolverResult& result);
  void charge(HostWork work, std::uint64_t count);

  const Scene& scene_;
  VisibilityBackend& visibility_;
  SolverOptions options_;
  HostCostSink* costs_;
  std::function<void(const StepProgress&)> progress_;
  AnswersObserver answers_;

  std::vector<Spectrum> radiosity_;
  std::vector<Spectrum> unshot_;
  std::vector<double> unshot_power_;  // by patch: unshot_[i].sum() x area, what scan_unshot reads
  double initial_max_power_ = 0;
  double energy_limit_ = 0;  // the emitted power plus the rounding of the sums that measure it
  double rounding_ = 0;      // relative rounding of one step's or the run's sums
  double shot_total_ = 0;
  double max_area_ = 0;      // the largest patch area (the delivery check's underflow allowance)    // every step's shot power, summed (the balance's rounding scales with it)
  int emission_exponent_ = 0;
  double step_scale_ = 1;    // what the last step multiplied its form factors by (1 unless normalised)
  Spectrum last_shot_;       // what the last step shot (for SolveDiverged's diagnosis)
  // Per-step scratch, kept to avoid reallocating every step.
  SegmentBatch batch_;
  PatchColumns columns_;  // the patches' geometry, for the sweep
  ReceiverSweep sweep_;   // this step's geometry and form factors, by patch
  std::vector<int> receivers_;
  // The shooter whose every receiver batch_.ends, batch_.end_faces and receivers_ hold (-1: none).
  int every_receiver_shooter_ = -1;
  std::vector<double> form_factors_;
  std::vector<std::uint8_t> blocked_;
  std::vector<double> shot_by_patch_, share_by_patch_;  // SolverResult::shot_power_by_patch, delivered_share_by_patch
  std::unique_ptr<SegmentFixer> fixer_;  // SolverOptions::fixes, when any
  SegmentBatch fixed_batch_;             // batch_ as the fixes move it
};

}  // namespace rc
