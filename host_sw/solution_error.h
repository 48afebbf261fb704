// How far one radiosity solution is from a reference one, pooled over patches and bands.
#pragma once

#include <vector>

#include "scenes/spectrum.h"

namespace rc {

struct SolutionError {
  double rmse = 0;               // sqrt(mean over patches and bands of (B - B_ref)^2)
  double max_abs = 0;            // max over patches and bands of |B - B_ref|
  double reference_mean = 0;     // mean over patches and bands of B_ref
  // Both errors relative to the mean reference radiosity, so that dark patches (e.g. under a
  // block, B_ref ~ 0) do not turn a tiny absolute error into a huge relative one.
  double relative_rmse() const { return reference_mean > 0 ? rmse / reference_mean : 0; }
  double relative_max() const { return reference_mean > 0 ? max_abs / reference_mean : 0; }
};

// Throws std::invalid_argument unless both have one value per patch of the same scene.
SolutionError compare_solutions(const std::vector<Spectrum>& solution, const std::vector<Spectrum>& reference);

}  // namespace rc
