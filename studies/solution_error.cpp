#include "studies/solution_error.h"

#include "radiosity/render.h"

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
