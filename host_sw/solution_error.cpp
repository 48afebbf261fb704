#include "host_sw/solution_error.h"

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

}  // namespace rc
