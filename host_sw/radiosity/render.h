// The solution seen from the scene's camera: patches rasterised with smooth (Gouraud) shading
// between patch values, then tone-mapped to 8-bit sRGB.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "host_sw/radiosity/png_writer.h"
#include "scenes/scene.h"

namespace rc {

struct RenderOptions {
  int width = 512;
  int height = 512;
  int supersample = 2;       // samples per pixel along each axis
  double key = 0.18;         // mid-grey the log-average luminance maps to
  // The supersampled picture is drawn in bands of at most this many bytes of samples (whole output
  // rows; at least one row); the picture does not depend on it.
  std::size_t band_bytes = std::size_t{64} << 20;
};

// Linear radiosity per pixel (before tone mapping); `covered` marks pixels that hit a surface.
struct HdrImage {
  int width = 0, height = 0;
  std::vector<Spectrum> pixels;
  std::vector<bool> covered;
};

HdrImage render_radiosity(const Scene& scene, const std::vector<Spectrum>& radiosity,
                          const RenderOptions& options);
RgbImage tone_map(const HdrImage& hdr, double key);

// A picture is dark when at least kDarkPictureShare of its pixels have no channel above
// kDarkPixelLevel (of 255): the camera sees nothing lit (it looks past the scene, or from behind a
// wall), or nothing was lit. dark_picture_warning says so, with the share; "" for any other picture.
constexpr double kDarkPictureShare = 0.99;
constexpr int kDarkPixelLevel = 8;
std::string dark_picture_warning(const RgbImage& image);

}  // namespace rc
