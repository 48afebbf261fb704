// The picture is drawn in bands of supersampled rows so that its memory stays bounded (an
// 8192-pixel picture drawn whole took 10 GB); the bands must not change a single pixel.
#include <gtest/gtest.h>

#include <cstddef>
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

}  // namespace
}  // namespace rc
