// The picture is drawn in bands of supersampled rows so that its memory stays bounded (an
// 8192-pixel picture drawn whole took 10 GB); the bands must not change a single pixel.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "host_sw/radiosity/render.h"
#include "scenes/cornell_box.h"
#include "scenes/prepare.h"

namespace rc {
namespace {

// Radiosity that differs from patch to patch, so every triangle and its neighbours matter.
std::vector<Spectrum> varied_radiosity(const Scene& scene) {
  std::vector<Spectrum> out(scene.patches.size());
  for (std::size_t i = 0; i < out.size(); ++i) {
    for (std::size_t b = 0; b < kBands; ++b) out[i].band[b] = 0.01 * double((i * 7 + b * 13) % 101);
  }
  return out;
}

void expect_same_picture(const HdrImage& a, const HdrImage& b) {
  ASSERT_EQ(a.width, b.width);
  ASSERT_EQ(a.height, b.height);
  ASSERT_EQ(a.pixels.size(), b.pixels.size());
  std::size_t different = 0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) {
    for (std::size_t k = 0; k < kBands; ++k) different += a.pixels[i].band[k] != b.pixels[i].band[k];
    different += a.covered[i] != b.covered[i];
  }
  EXPECT_EQ(different, 0u);
}

TEST(Render, BandsDrawTheSamePictureAsOneWholeImage) {
  SceneOptions o;
  o.patch_levels = 2;
  const Scene scene = prepare_scene(o).scene;
  const std::vector<Spectrum> radiosity = varied_radiosity(scene);
  RenderOptions whole;
  whole.width = 96;
  whole.height = 70;  // not a multiple of any band below
  whole.supersample = 3;
  const HdrImage reference = render_radiosity(scene, radiosity, whole);
  std::size_t covered = 0;
  for (bool c : reference.covered) covered += c;
  EXPECT_GT(covered, reference.covered.size() / 2);  // the box fills most of the picture
  for (std::size_t band_bytes : {std::size_t{1}, std::size_t{96 * 3 * 3 * 33 * 4}, std::size_t{96 * 3 * 3 * 33 * 9}}) {
    RenderOptions banded = whole;
    banded.band_bytes = band_bytes;  // one output row, 4 rows, 9 rows per band
    expect_same_picture(render_radiosity(scene, radiosity, banded), reference);
  }
}

std::vector<Spectrum> scaled(std::vector<Spectrum> radiosity, double k) {
  for (Spectrum& s : radiosity)
    for (double& b : s.band) b *= k;
  return radiosity;
}

double mean_byte(const RgbImage& image) {
  double sum = 0;
  for (std::uint8_t p : image.pixels) sum += p;
  return sum / double(image.pixels.size());
}

// A scene's units are its own (docs/scenes.md), and its picture must not depend on them (issue 27):
// emission of 1e-10 gave an all-black picture with exit 0, the tone map's floor of 1e-9 swamping
// every pixel. Oracles: scaling a dim scene's radiosity by a power of two changes no byte (the
// scaling is exact, and the tone map brings the brightest pixel into [1, 2) either way), down into
// values near the subnormals; a dim scene scaled by 1e-10 or 1e-300 is drawn within a grey level of
// the same scene in [1, 2); and a scene whose brightest pixel is at least 1 is drawn as before.
TEST(Render, PicturesDoNotDependOnTheScenesUnits) {
  SceneOptions o;
  o.patch_levels = 1;
  const Scene scene = prepare_scene(o).scene;
  RenderOptions small;
  small.width = small.height = 48;
  const std::vector<Spectrum> unit = varied_radiosity(scene);  // brightest about 1
  const HdrImage hdr = render_radiosity(scene, scaled(unit, 0.75), small);  // brightest in [0.5, 1)
  const RgbImage reference = tone_map(hdr, small.key);
  EXPECT_GT(mean_byte(reference), 40);  // a picture, not a black square
  for (int e : {-1, -40, -300, -1000}) {
    const RgbImage dim = tone_map(render_radiosity(scene, scaled(unit, 0.75 * std::ldexp(1.0, e)), small), small.key);
    EXPECT_EQ(dim.pixels, reference.pixels) << "2^" << e;
  }
  for (double k : {1e-10, 1e-300}) {
    const RgbImage dim = tone_map(render_radiosity(scene, scaled(unit, 0.75 * k), small), small.key);
    ASSERT_EQ(dim.pixels.size(), reference.pixels.size());
    int worst = 0;
    for (std::size_t i = 0; i < dim.pixels.size(); ++i) worst = std::max(worst, std::abs(dim.pixels[i] - reference.pixels[i]));
    EXPECT_LE(worst, 1) << k;
  }
  // Bright scenes keep the tone map they had: the old floor of 1e-9 and no scaling. Written out as
  // the old operator, for one bright scene.
  const HdrImage bright = render_radiosity(scene, scaled(unit, 20), small);
  const RgbImage drawn = tone_map(bright, small.key);
  double log_sum = 0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < bright.pixels.size(); ++i) {
    if (!bright.covered[i]) continue;
    const Spectrum& p = bright.pixels[i];
    log_sum += std::log(1e-9 + 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]);
    ++count;
  }
  const double scale = small.key / std::exp(log_sum / double(count));
  std::size_t different = 0;
  for (std::size_t i = 0; i < bright.pixels.size(); ++i) {
    const Spectrum c = bright.pixels[i] * scale;
    const double compress = 1.0 / (1.0 + 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]);
    for (std::size_t b = 0; b < 3; ++b) {
      const double v = std::clamp(c[b] * compress, 0.0, 1.0);
      const double srgb = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
      different += drawn.pixels[i * 3 + b] != static_cast<std::uint8_t>(std::lround(srgb * 255.0));
    }
  }
  EXPECT_EQ(different, 0u);
}

}  // namespace
}  // namespace rc
