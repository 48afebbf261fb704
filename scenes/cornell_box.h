// The Cornell Box (Cornell University Program of Computer Graphics data, the paper's ref. [18]),
// embedded as the default scene. See docs/scenes.md for how its quirks are handled.
#pragma once

#include <vector>

#include "scenes/scene.h"

namespace rc {

// 76 samples, 400-700 nm every 4 nm.
struct SampledSpectrum {
  std::vector<double> values;
};

// Band means over R = [600, 700], G = [500, 600), B = [400, 500) nm of a 400-700 nm sampling.
Spectrum to_rgb_band_means(const SampledSpectrum& s);

SampledSpectrum cornell_white();
SampledSpectrum cornell_red();
SampledSpectrum cornell_green();
SampledSpectrum cornell_light_emission();  // piecewise linear 0, 8, 15.6, 18.4 at 400..700 nm

// The 16 Cornell quads, with the ceiling cut around the light (4 quads), as 38 faces in millimetres.
// Not normalised and not subdivided.
Scene cornell_box();

}  // namespace rc
