// How far one radiosity solution is from a reference one, pooled over patches and bands.
#pragma once

#include <vector>

#include "scenes/scene.h"
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

// A solution on finer patches averaged onto coarser ones of the same faces: each face's patches are
// split uniformly and in order (scenes/subdivide.h), so coarse patch c of a face covers fine
// patches c*4^d .. c*4^d + 4^d - 1 of it, all of equal area. `faces` faces, `levels` deeper by d.
std::vector<Spectrum> coarsen_solution(const std::vector<Spectrum>& fine, std::size_t faces, int levels_deeper);

// A solution on patches of a scene evaluated at the patches of a finer scene with the same faces,
// whose every patch lies inside one coarse patch of its face (uniform or adaptive splits of the
// same faces, scenes/adaptive_patches.h): each fine patch gets the value of the coarse patch that
// holds its centre. Throws std::invalid_argument if a fine patch's centre is in no patch of its face.
std::vector<Spectrum> sample_at_finer(const Scene& coarse, const std::vector<Spectrum>& solution, const Scene& fine);

// Relative RMSE of two linear images over the pixels both cover, against the reference's mean.
struct HdrImage;
double image_difference(const HdrImage& image, const HdrImage& reference);

}  // namespace rc
