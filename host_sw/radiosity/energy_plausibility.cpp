#include "host_sw/radiosity/energy_plausibility.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>

namespace rc {

namespace {

struct RayHits {
  int misses = 0;
  int back_hits = 0;
};

// Moller-Trumbore in double, two-sided: the segment parameter t in (0, 1] of the hit, or -1.
double hit_parameter(const Triangle& tri, const Vec3& start, const Vec3& d) {
  const Vec3 e1 = tri.v1 - tri.v0, e2 = tri.v2 - tri.v0;
  const Vec3 p = glm::cross(d, e2);
  const double det = glm::dot(e1, p);
  if (det == 0 || !std::isfinite(det)) return -1;
  const double inv = 1.0 / det;
  const Vec3 s = start - tri.v0;
  const double u = glm::dot(s, p) * inv;
  if (u < 0 || u > 1) return -1;
  const Vec3 q = glm::cross(s, e1);
  const double v = glm::dot(d, q) * inv;
  if (v < 0 || u + v > 1) return -1;
  const double t = glm::dot(e2, q) * inv;
  return t > 1e-9 && t <= 1 ? t : -1;
}

// Cosine-weighted directions about the patch's normal (a fixed, stratified set), each cast as a
// segment long enough to leave the normalised scene (inside the unit cube); the first face hit
// decides: none (the power leaves), its back (no patch receives it) or its front.
RayHits cast_rays(const Scene& scene, const std::vector<Vec3>& normals, int patch, int rays) {
  const Patch& p = scene.patches[patch];
  const Vec3 n = glm::normalize(p.normal);
  const Vec3 helper = std::fabs(n.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
  const Vec3 t = glm::normalize(glm::cross(n, helper)), b = glm::cross(n, t);
  constexpr double kReach = 4.0;  // beyond the unit cube's diagonal from any point in it
  RayHits hits;
  for (int k = 0; k < rays; ++k) {
    const double u1 = (k + 0.5) / rays;
    const double u2 = std::fmod(0.5 + k * 0.6180339887498949, 1.0);
    const double r = std::sqrt(u1), phi = 2 * M_PI * u2;
    const Vec3 d = (t * (r * std::cos(phi)) + b * (r * std::sin(phi)) + n * std::sqrt(1 - u1)) * kReach;
    double front = 2, back = 2;
    for (std::size_t f = 0; f < scene.faces.size(); ++f) {
      if (scene.sheets.same(static_cast<int>(f), p.face)) continue;
      const double hit = hit_parameter(scene.faces[f].tri, p.centre, d);
      if (hit < 0) continue;
      if (glm::dot(normals[f], d) < 0) {
        front = std::min(front, hit);
      } else {
        back = std::min(back, hit);
      }
    }
    if (front > 1 && back > 1) {
      ++hits.misses;
    } else if (back < front * (1 - 1e-9)) {  // a two-sided sheet's faces tie: the front one receives
      ++hits.back_hits;
    }
  }
  return hits;
}

std::string percent(double share) {
  std::ostringstream m;
  m.precision(share < 0.1 ? 2 : 3);
  m << 100 * share << "%";
  return m.str();
}

}  // namespace

Openness measure_openness(const Scene& scene, const SolverResult& result, int max_shooters, int max_rays,
                          std::uint64_t max_tests) {
  Openness o;
  const std::vector<double>& shot = result.shot_power_by_patch;
  const std::vector<double>& share = result.delivered_share_by_patch;
  if (shot.size() != scene.patches.size() || share.size() != shot.size() || scene.faces.empty()) return o;
  double total_shot = 0;
  for (double s : shot) total_shot += s;
  if (!(total_shot > 0) || !std::isfinite(total_shot)) return o;
  // Shooters drawn in proportion to the power they shot (systematic sampling over the cumulative
  // shot power, so the plain mean over the draws estimates the power-weighted mean); a shooter drawn
  // twice counts twice.
  std::vector<std::pair<int, int>> drawn;  // shooter, times drawn
  {
    double cumulative = 0;
    int k = 0;
    for (std::size_t i = 0; i < shot.size() && k < max_shooters; ++i) {
      cumulative += shot[i];
      int times = 0;
      while (k < max_shooters && (k + 0.5) / max_shooters * total_shot <= cumulative) ++k, ++times;
      if (times > 0) drawn.emplace_back(static_cast<int>(i), times);
    }
  }
  if (drawn.empty()) return o;
  const double budget = double(max_tests) / (double(drawn.size()) * double(scene.faces.size()));
  const int rays = static_cast<int>(std::clamp(budget, 8.0, double(max_rays)));
  std::vector<Vec3> normals(scene.faces.size());
  for (std::size_t f = 0; f < scene.faces.size(); ++f) {
    const Triangle& tri = scene.faces[f].tri;
    normals[f] = glm::cross(tri.v1 - tri.v0, tri.v2 - tri.v0);
  }
  double draws = 0, difference = 0, difference_squared = 0;
  for (const auto& [s, times] : drawn) {
    const RayHits hits = cast_rays(scene, normals, s, rays);
    const double escapes = double(hits.misses) / rays, back = double(hits.back_hits) / rays;
    const double booked = std::clamp(1 - share[s], -1.0, 1.0);
    draws += times;
    o.escapes += times * escapes;
    o.back_hits += times * back;
    o.booked_loss += times * booked;
    const double d = booked - escapes - back;
    difference += times * d;
    difference_squared += times * d * d;
  }
  o.shooters = static_cast<int>(drawn.size());
  o.rays_per_shooter = rays;
  o.escapes /= draws;
  o.back_hits /= draws;
  o.booked_loss /= draws;
  const double geometric = o.escapes + o.back_hits;
  // The allowance: three standard deviations of the rays' estimate and of the draw of shooters (the
  // spread of booked minus geometric loss between them), plus one ray's worth.
  const double ray_count = rays * draws;
  const double mean_difference = difference / draws;
  const double spread = std::max(0.0, difference_squared / draws - mean_difference * mean_difference) / draws;
  o.noise = 3 * std::sqrt(std::max(geometric * (1 - geometric), 1.0 / ray_count) / ray_count + spread) + 1 / ray_count;
  // The effective reflectance: the share of arriving power the receivers reflected.
  const double arrived = std::ldexp(total_shot, -result.emission_exponent) - result.energy.escaping;
  o.reflectance = arrived > 0 ? std::clamp(1 - result.energy.absorbed / arrived, 0.0, 1.0) : 0.0;
  double nearest = geometric;  // the end of the noise allowance nearest to what was booked
  if (o.booked_loss > geometric + o.noise) {
    nearest = geometric + o.noise;
  } else if (o.booked_loss < geometric - o.noise) {
    nearest = std::max(0.0, geometric - o.noise);
  } else {
    return o;
  }
  const auto radiosity_of = [&](double loss) {
    return 1 / std::max(1 - o.reflectance * (1 - loss), std::numeric_limits<double>::min());
  };
  o.factor = radiosity_of(o.booked_loss) / radiosity_of(nearest);
  o.excess = o.booked_loss - nearest;
  return o;
}

std::string implausible_energy_warning(const Openness& o, const SolverResult& result) {
  const bool factor_off = o.factor * kImplausibleEnergyFactor < 1 || o.factor > kImplausibleEnergyFactor;
  if (o.shooters == 0 || (!factor_off && std::fabs(o.excess) <= kImplausibleLossShare)) return "";
  std::ostringstream m;
  m.precision(3);
  const double geometric = o.escapes + o.back_hits;
  m << "the energy accounting is implausible for this scene: the solve booked " << percent(o.booked_loss)
    << " of each shot as escaping (" << o.shooters << " shooters drawn in proportion to the power they shot), but "
    << o.rays_per_shooter << " rays from each (cosine-weighted) find " << percent(geometric) << " leaving the scene";
  if (o.back_hits > 0) m << " or landing on the back of a face (" << percent(o.back_hits) << ")";
  m << " (the run's totals: emitted " << result.energy.emitted << ", absorbed " << result.energy.absorbed
    << ", escaping " << result.energy.escaping << "). With the reflectance the solve saw (" << o.reflectance
    << " on average) every bounce ";
  if (!factor_off) {
    m << (o.excess > 0 ? "loses" : "gains") << " the difference, which changes the radiosity by a factor of only " << o.factor
      << ", but the absorbed and escaping totals are wrong by about " << percent(std::fabs(o.excess))
      << " of the power shot: the form factors " << (o.excess > 0 ? "sum short of" : "deliver more than")
      << " what the geometry lets arrive. Try --form-factor analytic or smaller patches (--patch-levels, --patch-size)";
  } else if (o.factor < 1) {
    m << "loses the difference, so the radiosity is about " << 1 / o.factor
      << "x too low: the form factors sum short of the room the geometry closes (patches large against their "
         "distance to the rest of the room). Try smaller patches (--patch-levels, --patch-size)";
  } else {
    m << "gains the difference, so the radiosity is about " << o.factor
      << "x too high: the form factors deliver more than the geometry lets arrive. Try --form-factor analytic or "
         "smaller patches";
  }
  m << " (docs/radiosity.md, Energy plausibility)";
  return m.str();
}

std::vector<std::string> solver_end_notes(const Scene& scene, const SolverResult& result, int steps_asked) {
  std::vector<std::string> notes;
  if (result.exhausted) {
    std::ostringstream m;
    m.precision(3);
    m << "the solve stopped after " << result.steps << " steps, ";
    if (steps_asked > 0) {
      m << "before the " << steps_asked << " asked for";
    } else {
      m << "before converging";
    }
    m << ": the largest unshot power left is below 2^-960 of the solve's units (kSmallestShotPower), where a "
         "step's deliveries are subnormal numbers that keep fewer than 53 bits; nothing left to shoot changes the "
         "answer (convergence " << 100 * result.convergence_reached << "%, docs/radiosity.md, Guards)";
    notes.push_back(m.str());
  }
  if (!result.radiosity_solved.empty()) {
    std::size_t underflowed = 0, first = 0;
    for (std::size_t i = 0; i < result.radiosity.size(); ++i) {
      for (std::size_t b = 0; b < kBands; ++b) {
        if (result.radiosity_solved[i][b] != 0 && std::fabs(result.radiosity[i][b]) < std::numeric_limits<double>::min()) {
          if (underflowed++ == 0) first = i;
          break;
        }
      }
    }
    if (underflowed > 0) {
      notes.push_back(std::to_string(underflowed) + " of " + std::to_string(result.radiosity.size()) +
                      " patches (the first: " + describe_patch(scene, static_cast<int>(first)) +
                      ") have radiosity that underflows to zero or a subnormal number in the scene's units (the "
                      "emission is below 2^-256 and was solved scaled by 2^" + std::to_string(result.emission_exponent) +
                      "): patches.csv holds those values, the picture is drawn from the scaled solve; give the "
                      "emission in larger units (docs/radiosity.md, Guards)");
    }
  }
  if (std::string w = implausible_energy_warning(measure_openness(scene, result), result); !w.empty()) {
    notes.push_back(std::move(w));
  }
  return notes;
}

}  // namespace rc
