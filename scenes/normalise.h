// Scaling the scene into the unit cube (paper sec 3.3) so that the hardware can hold positions as
// unsigned 0.N fixed point and differences as signed 1.N.
#pragma once

#include "scenes/scene.h"

namespace rc {

// Largest coordinate after normalisation: 1 - 2^-31, strictly below 1, so floor(x * 2^N) fits in
// N bits for every width N <= 31.
constexpr double kMaxNormalisedCoordinate = 1.0 - 1.0 / 2147483648.0;

// Scales faces, patches and the camera by the power of two that brings the largest face coordinate
// magnitude into [0.5, 1), recorded in scene.normalisation. Exact (no rounding), so every later
// comparison of lengths and areas (refinement picks faces by area) comes out as at the scene's own
// size, while no length or area overflows or underflows however large or small the scene is
// (1e200, 1e-300). Throws std::invalid_argument naming the face for a coordinate that is not finite.
void rescale_by_power_of_two(Scene& scene);

// Uniform scale (aspect kept) and offset: the smallest corner goes to 0, the largest extent to
// kMaxNormalisedCoordinate. Faces, patches and the camera are transformed; radiosity is unchanged
// because form factors are scale-invariant. Works at any finite size (it rescales by a power of
// two first); a scene with no extent, one smaller than the smallest normal double (its coordinates
// have lost precision), or whose camera is no camera once normalised (check_camera) is refused
// with std::invalid_argument naming the scene.
void normalise(Scene& scene);

}  // namespace rc
