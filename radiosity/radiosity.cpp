#include "radiosity/radiosity.h"

#include <algorithm>
#include <stdexcept>

namespace rc {

ProgressiveRadiosity::ProgressiveRadiosity(const Scene& scene, VisibilityBackend& visibility,
                                           SolverOptions options, HostCostSink* costs)
    : scene_(scene), visibility_(visibility), options_(options), costs_(costs) {
  if (!(options_.convergence > 0 && options_.convergence < 1)) {
    throw std::invalid_argument("convergence must be in (0, 1), e.g. 0.995");
  }
  if (options_.fixed_steps < 0) throw std::invalid_argument("--steps must not be negative");
  if (scene_.patches.empty()) throw std::invalid_argument("scene has no patches");
}

void ProgressiveRadiosity::charge(HostWork work, std::uint64_t count) {
  if (costs_ && count) costs_->charge(work, count);
}

double ProgressiveRadiosity::unshot_power(int patch) const {
  return unshot_[patch].sum() * scene_.patches[patch].area;
}

// The patch with the most unshot power; the lowest index wins ties, so runs are deterministic.
int ProgressiveRadiosity::choose_shooter() const {
  int best = 0;
  double best_power = unshot_power(0);
  for (int i = 1; i < static_cast<int>(scene_.patches.size()); ++i) {
    const double p = unshot_power(i);
    if (p > best_power) best = i, best_power = p;
  }
  return best;
}

bool ProgressiveRadiosity::done(int steps, double max_unshot) const {
  if (options_.fixed_steps > 0) return steps >= options_.fixed_steps;
  if (steps < std::min(options_.min_steps, options_.max_steps)) return false;
  return steps >= options_.max_steps || max_unshot < (1.0 - options_.convergence) * initial_max_power_;
}

SolverResult ProgressiveRadiosity::run() {
  const int n = static_cast<int>(scene_.patches.size());
  radiosity_.assign(n, Spectrum{});
  unshot_.assign(n, Spectrum{});
  SolverResult result;
  for (int i = 0; i < n; ++i) {
    const Patch& p = scene_.patches[i];
    radiosity_[i] = unshot_[i] = scene_.material_of(p).emission;
    result.energy.emitted += unshot_power(i);
    result.max_initial_power = std::max(result.max_initial_power, unshot_power(i));
  }
  if (result.max_initial_power <= 0) throw std::invalid_argument("scene emits no light");
  initial_max_power_ = result.max_initial_power;
  visibility_.load_faces(scene_.face_triangles());

  int shooter = choose_shooter();
  charge(HostWork::PatchScan, n);
  while (!done(result.steps, unshot_power(shooter))) {
    shoot(shooter, result);
    ++result.steps;
    charge(HostWork::Step, 1);
    shooter = choose_shooter();
    charge(HostWork::PatchScan, n);
    if (progress_) progress_({result.steps, 1.0 - unshot_power(shooter) / initial_max_power_});
  }
  result.max_unshot_power = unshot_power(shooter);
  result.convergence_reached = 1.0 - result.max_unshot_power / initial_max_power_;
  result.converged = options_.fixed_steps > 0 ? false : result.max_unshot_power < (1.0 - options_.convergence) * initial_max_power_;
  for (int i = 0; i < n; ++i) result.energy.unshot += unshot_power(i);
  result.radiosity = radiosity_;
  return result;
}

void ProgressiveRadiosity::shoot(int shooter, SolverResult& result) {
  const Patch& s = scene_.patches[shooter];
  const Spectrum shot = unshot_[shooter];
  const double shot_power = shot.sum() * s.area;
  unshot_[shooter] = Spectrum{};

  // Receivers in front of the shooter and facing it get a segment; the rest get nothing.
  // Without culling (paper-faithful) those get a segment too, marked as not needed: the hardware
  // tests it, but no answer about it can change the solution (its form factor is 0).
  batch_.start = s.centre;
  batch_.source_face = s.face;
  batch_.shooter = shooter;
  batch_.ends.clear();
  batch_.end_faces.clear();
  batch_.needed.clear();
  receivers_.clear();
  geometry_.clear();
  bool all_needed = true;
  for (int j = 0; j < static_cast<int>(scene_.patches.size()); ++j) {
    if (j == shooter) continue;
    const Patch& r = scene_.patches[j];
    const PairGeometry g = pair_geometry(s.centre, s.normal, r.centre, r.normal);
    const bool exchanges = g.exchanges();
    if (options_.cull_receivers && !exchanges) {
      ++result.receivers_skipped;
      continue;
    }
    receivers_.push_back(j);
    geometry_.push_back(g);
    batch_.ends.push_back(r.centre);
    batch_.end_faces.push_back(r.face);
    batch_.needed.push_back(exchanges);
    all_needed &= exchanges;
  }
  if (all_needed) batch_.needed.clear();
  charge(HostWork::SegmentSetup, receivers_.size());
  result.segments += receivers_.size();
  const std::uint64_t tests_before = visibility_.tests_performed();
  visibility_.submit(batch_);

  // Form factors while visibility is being answered (overlaps on the board in concurrent mode).
  form_factors_.resize(receivers_.size());
  for (std::size_t k = 0; k < receivers_.size(); ++k) form_factors_[k] = form_factor(options_.form_factor, geometry_[k], s.area);
  charge(HostWork::FormFactor, receivers_.size());

  visibility_.collect(blocked_);
  if (visibility_.runs_on_host()) charge(HostWork::IntersectionTest, visibility_.tests_performed() - tests_before);

  double arrived = 0;
  std::uint64_t updated = 0;
  // Receivers that exchange energy and are not blocked are updated (and charged for); the others
  // are skipped, whatever the backend said about the unneeded ones.
  for (std::size_t k = 0; k < receivers_.size(); ++k) {
    if (!batch_.is_needed(k)) continue;
    if (blocked_[k]) {
      ++result.blocked_segments;
      continue;
    }
    const int j = receivers_[k];
    const Spectrum& rho = scene_.material_of(scene_.patches[j]).reflectance;
    // Power arriving at j is F_sj * shot_power = F_js * A_j / A_s * shot_power (reciprocity).
    const Spectrum incident = shot * form_factors_[k];  // irradiance-like: B_s F_js
    const Spectrum delta = rho * incident;
    radiosity_[j] += delta;
    unshot_[j] += delta;
    const double area = scene_.patches[j].area;
    arrived += incident.sum() * area;
    result.energy.absorbed += (incident.sum() - delta.sum()) * area;
    ++updated;
  }
  charge(HostWork::EnergyUpdate, updated);
  result.energy.escaping += shot_power - arrived;
}

}  // namespace rc
