#include "host_sw/radiosity/radiosity.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace rc {

ProgressiveRadiosity::ProgressiveRadiosity(const Scene& scene, VisibilityBackend& visibility,
                                           SolverOptions options, HostCostSink* costs)
    : scene_(scene), visibility_(visibility), options_(options), costs_(costs), columns_(scene) {
  if (!(options_.convergence > 0 && options_.convergence < 1)) {
    throw std::invalid_argument("convergence must be in (0, 1), e.g. 0.995");
  }
  if (options_.fixed_steps < 0) throw std::invalid_argument("--steps must not be negative");
  if (scene_.patches.empty()) throw std::invalid_argument("scene has no patches");
}

void ProgressiveRadiosity::charge(HostWork work, std::uint64_t count) {
  if (costs_ && count) costs_->charge(work, count);
}

double ProgressiveRadiosity::unshot_power(int patch) const { return unshot_power_[patch]; }

void ProgressiveRadiosity::set_unshot(int patch, const Spectrum& unshot) {
  unshot_[patch] = unshot;
  unshot_power_[patch] = unshot.sum() * columns_.area[patch];
}

// The first maximum, as a single loop finds it (the comparison is rarely true, so its branch is
// predicted). The limit test needs no sum in index order, which waits on every addition in turn:
// four partial sums run side by side. For n non-negative terms both orders lie within
// n u (1 + n u) of the exact sum (Higham, u = epsilon / 2), so the index-order total is at most
// the four-way one times (1 + 2 n epsilon); where that stays below the limit, so does the
// index-order sum. Elsewhere (a total near the limit, a negative term or one that is not finite)
// within_limit is false.
PowerScan scan_powers(const double* power, std::size_t n, double limit) {
  constexpr std::size_t kLanes = 4;
  double sum[kLanes] = {0, 0, 0, 0}, best = power[0];
  std::size_t first = 0;
  bool negative = false;
  const auto visit = [&](std::size_t i, double& lane) {
    const double p = power[i];
    lane += p;
    negative |= p < 0;
    if (p > best) best = p, first = i;
  };
  std::size_t i = 0;
  for (; i + kLanes <= n; i += kLanes) {
    for (std::size_t l = 0; l < kLanes; ++l) visit(i + l, sum[l]);
  }
  for (; i < n; ++i) visit(i, sum[0]);
  const double total = ((sum[0] + sum[1]) + sum[2]) + sum[3];
  const double order_bound = 1.0 + 4.0 * double(n + 2) * std::numeric_limits<double>::epsilon();
  return {first, !negative && std::isfinite(total) && total * order_bound <= limit};
}

// The patch with the most unshot power; the lowest index wins ties, so runs are deterministic.
// The same pass tells whether the energy guard's total is surely within its limit; only when it
// is not does the guard sum it (unshot_total, in index order, as run() sums the emitted power).
ProgressiveRadiosity::UnshotScan ProgressiveRadiosity::scan_unshot() const {
  const PowerScan s = scan_powers(unshot_power_.data(), unshot_power_.size(), energy_limit_);
  return {static_cast<int>(s.first_maximum), s.within_limit};
}

double ProgressiveRadiosity::unshot_total() const {
  double total = unshot_power_[0];
  for (std::size_t i = 1; i < unshot_power_.size(); ++i) total += unshot_power_[i];
  return total;
}

bool ProgressiveRadiosity::done(int steps, double max_unshot) const {
  if (max_unshot < kSmallestShotPower) return true;  // nothing normal left to shoot (run() says so)
  if (options_.fixed_steps > 0) return steps >= options_.fixed_steps;
  if (steps < std::min(options_.min_steps, options_.max_steps)) return false;
  return steps >= options_.max_steps || max_unshot < (1.0 - options_.convergence) * initial_max_power_;
}

namespace {

// The power of two that brings the largest emission into [0.5, 1) when it lies below
// kSmallestUnscaledEmission; 0 otherwise (and for a scene that emits nothing: refused later).
int emission_exponent(const Scene& scene) {
  double largest = 0;
  for (const Patch& p : scene.patches) largest = std::fmax(largest, scene.material_of(p).emission.max());
  if (!(largest > 0) || largest >= kSmallestUnscaledEmission) return 0;
  int exponent = 0;
  std::frexp(largest, &exponent);
  return -exponent;
}

Spectrum scaled(Spectrum s, int exponent) {
  if (exponent != 0) {
    for (double& b : s.band) b = std::ldexp(b, exponent);
  }
  return s;
}

}  // namespace

SolverResult ProgressiveRadiosity::run() {
  const int n = static_cast<int>(scene_.patches.size());
  radiosity_.assign(n, Spectrum{});
  unshot_.assign(n, Spectrum{});
  unshot_power_.assign(n, 0.0);
  shot_by_patch_.assign(n, 0.0);
  share_by_patch_.assign(n, 0.0);
  emission_exponent_ = emission_exponent(scene_);
  shot_total_ = 0;
  SolverResult result;
  result.emission_exponent = emission_exponent_;
  result.form_factor_sums.normalised = options_.form_factor == FormFactorKind::Analytic;
  for (int i = 0; i < n; ++i) {
    const Patch& p = scene_.patches[i];
    radiosity_[i] = scaled(scene_.material_of(p).emission, emission_exponent_);
    set_unshot(i, radiosity_[i]);
    result.energy.emitted += unshot_power(i);
    result.max_initial_power = std::max(result.max_initial_power, unshot_power(i));
  }
  if (!std::isfinite(result.energy.emitted)) {
    throw std::invalid_argument("the emitted power (emission x area, summed over patches and bands) is not finite: "
                                "the emission values are too large");
  }
  if (result.max_initial_power <= 0) throw std::invalid_argument("scene emits no light");
  initial_max_power_ = result.max_initial_power;
  max_area_ = 0;
  for (int i = 0; i < n; ++i) max_area_ = std::max(max_area_, columns_.area[i]);
  // Energy guard. With exact form factors (summing to at most 1 over a shooter's receivers) and
  // rho < 1, every step loses energy, so the total unshot power never exceeds the emitted power.
  // The point and disc rules can overshoot near a patch (the default Cornell solve with point form
  // factors has 639 of 4064 steps that deliver more than they shot, up to 3.37 times), but in every
  // converging solve measured the total stays below the emitted power (at most 0.9988 of it,
  // docs/radiosity.md, Guards); a solve that diverges grows it geometrically. So exceeding the
  // emitted power is the error. The computed sums differ from the exact ones by at most (n + 2) u
  // relative each (Higham's bound for recursive summation of n products of 3-band sums,
  // u = epsilon / 2); the limit allows twice that.
  rounding_ = 2.0 * (n + 2) * std::numeric_limits<double>::epsilon();
  energy_limit_ = result.energy.emitted * (1.0 + rounding_);
  if (options_.fixes.any()) {  // the fixes' faces: rounded to their coordinate grid when they set one
    fixer_ = std::make_unique<SegmentFixer>(scene_.face_triangles(), scene_.sheets, options_.fixes);
    visibility_.load_faces(fixer_->faces(), scene_.sheets);
  } else {
    visibility_.load_faces(scene_.face_triangles(), scene_.sheets);
  }
  every_receiver_shooter_ = -1;

  UnshotScan scan = scan_unshot();
  charge(HostWork::PatchScan, n);
  while (!done(result.steps, unshot_power(scan.shooter))) {
    const int shooter = scan.shooter;
    shoot(shooter, result);
    ++result.steps;
    charge(HostWork::Step, 1);
    scan = scan_unshot();
    charge(HostWork::PatchScan, n);
    if (!scan.within_limit) check_energy(result.steps, shooter, unshot_total(), result);
    check_balance(result.steps, shooter, result);
    if (progress_) progress_({result.steps, 1.0 - unshot_power(scan.shooter) / initial_max_power_});
  }
  check_radiosity_finite(result.steps);
  const int shooter = scan.shooter;
  result.max_unshot_power = unshot_power(shooter);
  result.convergence_reached = 1.0 - result.max_unshot_power / initial_max_power_;
  result.converged = options_.fixed_steps > 0 ? false : result.max_unshot_power < (1.0 - options_.convergence) * initial_max_power_;
  // Stopped for want of normal powers before the steps asked for, or before converging.
  result.exhausted = result.max_unshot_power < kSmallestShotPower &&
                     (options_.fixed_steps > 0 ? result.steps < options_.fixed_steps : !result.converged);
  for (int i = 0; i < n; ++i) result.energy.unshot += unshot_power(i);
  result.radiosity = radiosity_;
  result.shot_power_by_patch = shot_by_patch_;
  result.delivered_share_by_patch = share_by_patch_;
  if (emission_exponent_ != 0) {  // back to the scene's units (exact, barring underflow of the output)
    result.radiosity_solved = radiosity_;
    for (Spectrum& b : result.radiosity) b = scaled(b, -emission_exponent_);
    for (double* power : {&result.max_initial_power, &result.max_unshot_power, &result.energy.emitted,
                          &result.energy.absorbed, &result.energy.escaping, &result.energy.unshot}) {
      *power = unscaled(*power);
    }
  }
  return result;
}

// Only the receivers that exchange energy with the shooter, in patch order.
void ProgressiveRadiosity::select_exchanging_receivers(int shooter, SolverResult& result) {
  every_receiver_shooter_ = -1;
  batch_.ends.clear();
  batch_.end_faces.clear();
  batch_.needed.clear();
  receivers_.clear();
  for (int j = 0; j < static_cast<int>(columns_.size()); ++j) {
    if (j == shooter) continue;
    if (!sweep_.exchanges[j]) {
      ++result.receivers_skipped;
      continue;
    }
    receivers_.push_back(j);
    batch_.ends.push_back(columns_.centre[j]);
    batch_.end_faces.push_back(columns_.face[j]);
  }
}

// Every patch but the shooter, in patch order (the paper's rule), those that exchange no energy
// marked as not needed (no mark when every one is needed).
void ProgressiveRadiosity::select_every_receiver(int shooter) {
  const std::size_t n = columns_.size(), s = static_cast<std::size_t>(shooter);
  const auto without_shooter = [&](auto& to, const auto& from) {
    to.assign(from.begin(), from.begin() + static_cast<std::ptrdiff_t>(s));
    to.insert(to.end(), from.begin() + static_cast<std::ptrdiff_t>(s) + 1, from.end());
  };
  // Entry k is patch k below the shooter and k + 1 from it on. The entries built for the previous
  // shooter differ from these only between the two shooters: below both they are the same
  // patches, above both the same patches shifted by one.
  std::size_t lo = 0, hi = n - 1;
  if (every_receiver_shooter_ >= 0 && receivers_.size() == n - 1) {
    const auto previous = static_cast<std::size_t>(every_receiver_shooter_);
    lo = std::min(s, previous);
    hi = std::max(s, previous);
  } else {
    receivers_.resize(n - 1);
    batch_.ends.resize(n - 1);
    batch_.end_faces.resize(n - 1);
  }
  for (std::size_t k = lo; k < hi; ++k) {
    const std::size_t patch = k < s ? k : k + 1;
    receivers_[k] = static_cast<int>(patch);
    batch_.ends[k] = columns_.centre[patch];
    batch_.end_faces[k] = columns_.face[patch];
  }
  every_receiver_shooter_ = shooter;
  without_shooter(batch_.needed, sweep_.exchanges);
  if (std::all_of(batch_.needed.begin(), batch_.needed.end(), [](std::uint8_t x) { return x != 0; })) batch_.needed.clear();
}

double ProgressiveRadiosity::delivered_share(const Patch& shooter) const {
  double sum = 0;
  for (std::size_t k = 0; k < receivers_.size(); ++k) {
    if (batch_.is_needed(k) && !blocked_[k]) sum += form_factors_[k] * columns_.area[receivers_[k]];
  }
  return sum / shooter.area;
}

void ProgressiveRadiosity::shoot(int shooter, SolverResult& result) {
  const Patch& s = scene_.patches[shooter];
  const Spectrum shot = unshot_[shooter];
  last_shot_ = shot;
  const double shot_power = shot.sum() * s.area;
  shot_total_ += shot_power;
  set_unshot(shooter, Spectrum{});

  // Receivers in front of the shooter and facing it get a segment; the rest get nothing.
  // Without culling (paper-faithful) those get a segment too, marked as not needed: the hardware
  // tests it, but no answer about it can change the solution (its form factor is 0).
  sweep_receivers(columns_, shooter, options_.form_factor, sweep_);
  batch_.start = s.centre;
  batch_.source_face = s.face;
  batch_.shooter = shooter;
  if (options_.cull_receivers) {
    select_exchanging_receivers(shooter, result);
  } else {
    select_every_receiver(shooter);
  }
  charge(HostWork::SegmentSetup, receivers_.size());
  result.segments += receivers_.size();
  const std::uint64_t tests_before = visibility_.tests_performed();
  if (fixer_) {
    fixed_batch_ = batch_;
    fixer_->adjust(fixed_batch_);
    visibility_.submit(fixed_batch_);
  } else {
    visibility_.submit(batch_);
  }

  // Form factors while visibility is being answered (overlaps on the board in concurrent mode): the
  // point and disc rules' came with the sweep; the analytic rule integrates over the shooter.
  form_factors_.resize(receivers_.size());
  if (options_.form_factor == FormFactorKind::Analytic) {
    for (std::size_t k = 0; k < receivers_.size(); ++k) {
      const Patch& r = scene_.patches[receivers_[k]];
      form_factors_[k] = form_factor(options_.form_factor, sweep_.geometry(receivers_[k]), s.tri, s.area, r.centre, r.normal);
    }
  } else {
    for (std::size_t k = 0; k < receivers_.size(); ++k) form_factors_[k] = sweep_.form_factor[receivers_[k]];
  }
  charge(HostWork::FormFactor, receivers_.size());

  visibility_.collect(blocked_);
  if (visibility_.runs_on_host()) charge(HostWork::IntersectionTest, visibility_.tests_performed() - tests_before);
  if (fixer_ && options_.fixes.neighbour_rings != 0) {  // the neighbour rule's re-tests run on the host
    const std::uint64_t fix_tests_before = fixer_->tests_performed(), cleared_before = fixer_->segments_cleared();
    fixer_->recheck(fixed_batch_, blocked_);
    charge(HostWork::IntersectionTest, fixer_->tests_performed() - fix_tests_before);
    result.fix_tests += fixer_->tests_performed() - fix_tests_before;
    result.fix_cleared += fixer_->segments_cleared() - cleared_before;
  }
  // The answers the solver uses (after the neighbour rule), for the segments it asked (before any
  // offset): a fidelity sample checks those against double precision.
  if (answers_) answers_(batch_, blocked_);

  // The share of the shot power the step delivers; above 1 the step creates energy. The analytic
  // rule scales the deliveries back to what was shot (docs/radiosity.md, Form-factor sums).
  const double share = delivered_share(s);
  FormFactorSums& sums = result.form_factor_sums;
  if (share > 1) ++sums.steps_above_one;
  if (share > sums.largest) sums.largest = share, sums.largest_step = result.steps + 1, sums.largest_shooter = shooter;
  step_scale_ = sums.normalised && share > 1 ? 1.0 / share : 1.0;
  shot_by_patch_[shooter] += shot_power;
  share_by_patch_[shooter] = share * step_scale_;

  double arrived = 0;
  // The run's absorbed power and blocked count, added to in registers: through `result` every
  // addition would wait for the previous one's store (the same additions, in the same order).
  double absorbed = result.energy.absorbed;
  std::uint64_t updated = 0, blocked = 0;
  // Receivers that exchange energy and are not blocked are updated (and charged for); the others
  // are skipped, whatever the backend said about the unneeded ones.
  for (std::size_t k = 0; k < receivers_.size(); ++k) {
    if (!batch_.is_needed(k)) continue;
    if (blocked_[k]) {
      ++blocked;
      continue;
    }
    const int j = receivers_[k];
    const Spectrum& rho = columns_.reflectance[j];
    // Power arriving at j is F_sj * shot_power = F_js * A_j / A_s * shot_power (reciprocity).
    const Spectrum incident = shot * (form_factors_[k] * step_scale_);  // irradiance-like: B_s F_js
    const Spectrum delta = rho * incident;
    radiosity_[j] += delta;
    Spectrum& unshot = unshot_[j];  // set_unshot, inline: this loop runs for every delivery
    unshot += delta;
    const double area = columns_.area[j];
    unshot_power_[j] = unshot.sum() * area;
    arrived += incident.sum() * area;
    absorbed += (incident.sum() - delta.sum()) * area;
    ++updated;
  }
  result.energy.absorbed = absorbed;
  result.blocked_segments += blocked;
  charge(HostWork::EnergyUpdate, updated);
  result.energy.escaping += shot_power - arrived;
  // Relative rounding, plus the absolute rounding of deliveries that are subnormal numbers (a tiny
  // form factor times a small shot): at most 2^-1074 per band and product, per receiver.
  const double underflow = double(updated) * 8.0 * std::numeric_limits<double>::denorm_min() * std::max(1.0, max_area_);
  if (sums.normalised && !(arrived <= shot_power * (1 + rounding_) + underflow)) {
    std::ostringstream m;
    m.precision(17);
    m << "internal error: step " << result.steps + 1 << " delivered " << unscaled(arrived) << " of the "
      << unscaled(shot_power) << " that " << patch_name(shooter)
      << " shot with the analytic form factor, which is normalised never to deliver more (a bug; please report it)";
    throw SolveDiverged(m.str());
  }
}

namespace {

// Vertices of `a` that are also vertices of `b` (exact coordinates: faces that meet share them).
int shared_vertices(const Triangle& a, const Triangle& b) {
  int shared = 0;
  for (const Vec3& v : {a.v0, a.v1, a.v2}) shared += v == b.v0 || v == b.v1 || v == b.v2;
  return shared;
}

}  // namespace

std::string describe_patch(const Scene& scene, int patch) {
  const int face = scene.patches[patch].face;
  const int surface = scene.faces[face].surface;
  std::string name = "patch " + std::to_string(patch) + " (face " + std::to_string(face);
  if (const std::string surface_name = scene.surface_name(surface); !surface_name.empty()) {
    name += ", surface '" + surface_name + "'";
  }
  return name + ")";
}

std::string form_factor_sum_warning(const Scene& scene, const SolverResult& result, FormFactorKind kind) {
  const FormFactorSums& f = result.form_factor_sums;
  if (kind == FormFactorKind::Analytic || f.steps_above_one == 0) return "";
  std::ostringstream m;
  m.precision(4);
  m << f.steps_above_one << " of " << result.steps << " steps delivered more power than their shooter shot (the "
    << to_string(kind) << " form factors to a shooter's unblocked receivers, times receiver over shooter area, summed "
    << "above 1: those steps create energy); the worst: step " << f.largest_step << ", shooter "
    << describe_patch(scene, f.largest_shooter) << ", sum " << f.largest
    << ". --form-factor analytic never creates energy (docs/radiosity.md, Form-factor sums)";
  return m.str();
}

// What the last step did, from its scratch (still intact): the receiver with the largest form
// factor, how much power the step put back into unshot, and what to try.
std::string ProgressiveRadiosity::last_step_diagnosis(int shooter) const {
  const Patch& s = scene_.patches[shooter];
  const double shot_power = last_shot_.sum() * s.area;
  const double scale = step_scale_;
  double reflected = 0;
  std::size_t largest = receivers_.size();
  for (std::size_t k = 0; k < receivers_.size(); ++k) {
    if (!batch_.is_needed(k) || blocked_[k]) continue;
    const Patch& r = scene_.patches[receivers_[k]];
    reflected += (scene_.material_of(r).reflectance * last_shot_ * (form_factors_[k] * scale)).sum() * r.area;
    if (largest == receivers_.size() || !(form_factors_[k] <= form_factors_[largest])) largest = k;
  }
  std::ostringstream m;
  m.precision(6);
  m << "That step shot " << unscaled(shot_power) << " from " << patch_name(shooter) << " and gave "
    << unscaled(reflected) << " back to unshot power";
  bool folded = false;
  if (largest < receivers_.size()) {
    const int r = receivers_[largest];
    const double F = form_factors_[largest];
    m << "; its largest form factor (" << to_string(options_.form_factor) << "), to " << patch_name(r)
      << " at distance " << std::sqrt(sweep_.distance_squared[r]) << ", is " << F;
    if (!(F <= 1)) m << " (above 1: the patches are close against their size)";
    // Two faces that share an edge and face each other: a fold. Its form factor does not shrink
    // with the patches (the geometry near the edge is the same at every scale).
    const Face& face_s = scene_.faces[s.face];
    const Face& face_r = scene_.faces[scene_.patches[r].face];
    folded = s.face != scene_.patches[r].face && shared_vertices(face_s.tri, face_r.tri) >= 2;
    if (folded) {
      const double degrees = std::acos(std::clamp(glm::dot(s.normal, scene_.patches[r].normal), -1.0, 1.0)) * 180 / M_PI;
      m << ". Faces " << s.face << " and " << scene_.patches[r].face << " share an edge and fold onto each other "
        << "(their normals are " << std::lround(degrees) << " degrees apart)";
      if (face_s.surface == face_r.surface) m << ": the two triangles of one quad, which is not planar; fix its vertices";
    }
  }
  m << ". Try ";
  if (options_.form_factor != FormFactorKind::Analytic) m << "--form-factor analytic (never creates energy), ";
  if (!folded) {
    m << "smaller patches (--patch-levels, --patch-size) so that no patch is large against its distance to its "
         "neighbours, or check the scene for surfaces that fold onto each other";
  } else {
    m << "opening the fold (smaller patches do not help: the form factor across a fold is the same at every "
         "patch size)";
  }
  m << " (docs/radiosity.md, Guards)";
  return m.str();
}

void ProgressiveRadiosity::check_energy(int step, int shooter, double total_unshot, const SolverResult& result) const {
  if (std::isfinite(total_unshot) && total_unshot <= energy_limit_) return;
  std::ostringstream m;
  m.precision(6);
  m << "the solve diverged at step " << step << ": ";
  if (!std::isfinite(total_unshot)) {
    m << "the total unshot power is " << total_unshot << " (not finite)";
  } else {
    m << "the total unshot power " << unscaled(total_unshot) << " exceeds the emitted power "
      << unscaled(result.energy.emitted) << " (the form factors create energy; a solve that converges only loses it)";
  }
  throw SolveDiverged(m.str() + ". " + last_step_diagnosis(shooter));
}

// absorbed + escaping + unshot = emitted and unshot >= 0, so absorbed can exceed emitted only where
// escaping went below zero: more power arrived than was ever shot. That is the impossible answer
// (absorbed power that was never emitted), caught even where rho = 0 keeps unshot at 0, which
// check_energy alone would miss. Escaping below zero alone is not refused: the point and disc rules
// deliver more than a shooter shot on coarse patches (warned once, form_factor_sum_warning) and the
// run can still absorb less than was emitted; with analytic no step delivers more than it shot
// (checked in shoot). Each step's sums round by at most rounding_ relative to the power it shot, so
// the run's by rounding_ x (emitted + every shot).
void ProgressiveRadiosity::check_balance(int step, int shooter, const SolverResult& result) const {
  const double tolerance = rounding_ * (result.energy.emitted + shot_total_);
  if (result.energy.absorbed <= result.energy.emitted + tolerance) return;
  std::ostringstream m;
  m.precision(6);
  m << "the solve created energy at step " << step << ": emitted " << unscaled(result.energy.emitted)
    << ", absorbed " << unscaled(result.energy.absorbed) << ", escaping " << unscaled(result.energy.escaping)
    << " (more absorbed than emitted, beyond rounding). " << last_step_diagnosis(shooter);
  throw SolveDiverged(m.str());
}

void ProgressiveRadiosity::check_radiosity_finite(int steps) const {
  for (int i = 0; i < static_cast<int>(radiosity_.size()); ++i) {
    for (double b : radiosity_[i].band) {
      if (std::isfinite(b)) continue;
      std::ostringstream m;
      m << "the solve diverged: after " << steps << " steps the radiosity of " << patch_name(i) << " is " << b
        << " (not finite); try --form-factor analytic or smaller patches (docs/radiosity.md, Guards)";
      throw SolveDiverged(m.str());
    }
  }
}

}  // namespace rc
