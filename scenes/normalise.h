// Scaling the scene into the unit cube (paper sec 3.3) so that the hardware can hold positions as
// unsigned 0.N fixed point and differences as signed 1.N.
#pragma once

#include "scenes/scene.h"

namespace rc {

// Largest coordinate after normalisation: 1 - 2^-31, strictly below 1, so floor(x * 2^N) fits in
// N bits for every width N <= 31.
constexpr double kMaxNormalisedCoordinate = 1.0 - 1.0 / 2147483648.0;

// Uniform scale (aspect kept) and offset: the smallest corner goes to 0, the largest extent to
// kMaxNormalisedCoordinate. Faces, patches and the camera are transformed; radiosity is unchanged
// because form factors are scale-invariant.
void normalise(Scene& scene);

}  // namespace rc
