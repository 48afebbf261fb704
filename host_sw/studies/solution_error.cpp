#include "host_sw/studies/solution_error.h"

#include <algorithm>

#include "host_sw/radiosity/render.h"

#include <cmath>
#include <stdexcept>

namespace rc {

SolutionError compare_solutions(const std::vector<Spectrum>& solution, const std::vector<Spectrum>& reference) {
  if (solution.size() != reference.size() || reference.empty()) {
    throw std::invalid_argument("solutions to compare must cover the same, non-empty set of patches");
  }
  SolutionError e;
  double squares = 0;
  for (std::size_t i = 0; i < reference.size(); ++i) {
    for (std::size_t b = 0; b < kBands; ++b) {
      const double d = solution[i][b] - reference[i][b];
      squares += d * d;
      e.max_abs = std::max(e.max_abs, std::abs(d));
      e.reference_mean += reference[i][b];
    }
  }
  const double n = static_cast<double>(reference.size() * kBands);
  e.rmse = std::sqrt(squares / n);
  e.reference_mean /= n;
  return e;
}

std::vector<Spectrum> coarsen_solution(const std::vector<Spectrum>& fine, std::size_t faces, int levels_deeper) {
  if (levels_deeper < 0 || faces == 0) throw std::invalid_argument("coarsen_solution: bad face count or depth");
  const std::size_t group = std::size_t(1) << (2 * levels_deeper);
  if (fine.size() % (faces * group) != 0) {
    throw std::invalid_argument("coarsen_solution: " + std::to_string(fine.size()) + " patches do not split into " +
                                std::to_string(faces) + " faces of groups of " + std::to_string(group));
  }
  std::vector<Spectrum> coarse(fine.size() / group);
  for (std::size_t c = 0; c < coarse.size(); ++c) {
    Spectrum sum;
    for (std::size_t j = 0; j < group; ++j) sum += fine[c * group + j];
    coarse[c] = sum * (1.0 / static_cast<double>(group));
  }
  return coarse;
}

namespace {

// Whether `p` (in the triangle's plane) lies in the triangle, edges included up to rounding.
bool contains(const Triangle& t, const Vec3& p) {
  const Vec3 n = glm::cross(t.v1 - t.v0, t.v2 - t.v0);
  const double scale = glm::dot(n, n);
  const double slack = -1e-9 * scale;
  return glm::dot(glm::cross(t.v1 - t.v0, p - t.v0), n) >= slack && glm::dot(glm::cross(t.v2 - t.v1, p - t.v1), n) >= slack &&
         glm::dot(glm::cross(t.v0 - t.v2, p - t.v2), n) >= slack;
}

}  // namespace

std::vector<Spectrum> sample_at_finer(const Scene& coarse, const std::vector<Spectrum>& solution, const Scene& fine) {
  if (solution.size() != coarse.patches.size()) throw std::invalid_argument("sample_at_finer: one value per coarse patch");
  if (coarse.faces.size() != fine.faces.size()) throw std::invalid_argument("sample_at_finer: the scenes' faces differ");
  std::vector<std::vector<std::size_t>> by_face(coarse.faces.size());
  for (std::size_t i = 0; i < coarse.patches.size(); ++i) by_face[static_cast<std::size_t>(coarse.patches[i].face)].push_back(i);
  std::vector<Spectrum> out;
  out.reserve(fine.patches.size());
  for (const Patch& p : fine.patches) {
    const std::vector<std::size_t>& candidates = by_face[static_cast<std::size_t>(p.face)];
    const auto holder = std::find_if(candidates.begin(), candidates.end(),
                                     [&](std::size_t c) { return contains(coarse.patches[c].tri, p.centre); });
    if (holder == candidates.end())
      throw std::invalid_argument("sample_at_finer: a patch centre of face " + std::to_string(p.face) + " is in no coarse patch");
    out.push_back(solution[*holder]);
  }
  return out;
}

double image_difference(const HdrImage& image, const HdrImage& reference) {
  if (image.width != reference.width || image.height != reference.height) {
    throw std::invalid_argument("image_difference: images of different sizes");
  }
  double squares = 0, mean = 0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < reference.pixels.size(); ++i) {
    if (!image.covered[i] || !reference.covered[i]) continue;
    for (std::size_t b = 0; b < kBands; ++b) {
      const double d = image.pixels[i][b] - reference.pixels[i][b];
      squares += d * d;
      mean += reference.pixels[i][b];
      ++n;
    }
  }
  return n && mean > 0 ? std::sqrt(squares / n) / (mean / n) : 0.0;
}

}  // namespace rc
