#include "scenes/adaptive_patches.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <stdexcept>
#include <tuple>

#include "scenes/subdivide.h"

namespace rc {

double luminance(const Spectrum& s) {
  if (kBands == 3) return 0.2126 * s[0] + 0.7152 * s[1] + 0.0722 * s[2];
  double sum = 0;
  for (std::size_t b = 0; b < kBands; ++b) sum += s[b];
  return sum / static_cast<double>(kBands);
}

std::vector<double> radiosity_gradients(const Scene& scene, const std::vector<Spectrum>& radiosity) {
  if (radiosity.size() != scene.patches.size())
    throw std::invalid_argument("radiosity_gradients: one value per patch expected");
  std::vector<double> y(radiosity.size());
  double brightest = 0;
  for (std::size_t i = 0; i < y.size(); ++i) brightest = std::max(brightest, y[i] = luminance(radiosity[i]));
  // Patches by (face, corner).
  using Corner = std::tuple<int, double, double, double>;
  std::map<Corner, std::vector<std::size_t>> at;
  for (std::size_t i = 0; i < scene.patches.size(); ++i) {
    const Patch& p = scene.patches[i];
    for (const Vec3& v : {p.tri.v0, p.tri.v1, p.tri.v2}) at[{p.face, v.x, v.y, v.z}].push_back(i);
  }
  std::vector<double> gradient(y.size(), 0.0);
  if (brightest <= 0) return gradient;
  for (const auto& [corner, patches] : at) {
    for (std::size_t a : patches)
      for (std::size_t b : patches) gradient[a] = std::max(gradient[a], std::abs(y[a] - y[b]) / brightest);
  }
  return gradient;
}

int patch_depth(const Scene& scene, const Patch& patch) {
  const double ratio = scene.faces[patch.face].tri.area() / patch.area;
  return static_cast<int>(std::lround(std::log(ratio) / std::log(4.0)));
}

std::vector<Patch> split_steepest(const Scene& scene, const std::vector<double>& gradients, std::size_t count,
                                  int max_depth) {
  if (gradients.size() != scene.patches.size())
    throw std::invalid_argument("split_steepest: one gradient per patch expected");
  std::vector<std::size_t> order(gradients.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return gradients[a] > gradients[b]; });
  std::vector<bool> split(gradients.size(), false);
  std::size_t chosen = 0;
  for (std::size_t i : order) {
    if (chosen == count) break;
    if (patch_depth(scene, scene.patches[i]) >= max_depth) continue;
    split[i] = true;
    ++chosen;
  }
  std::vector<Patch> out;
  out.reserve(scene.patches.size() + 3 * chosen);
  for (std::size_t i = 0; i < scene.patches.size(); ++i) {
    const Patch& p = scene.patches[i];
    if (!split[i]) {
      out.push_back(p);
      continue;
    }
    for (const Triangle& t : split4(p.tri)) out.push_back({t, p.face, t.centroid(), p.normal, t.area()});
  }
  return out;
}

}  // namespace rc
