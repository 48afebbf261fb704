#include "host_sw/radiosity/render.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>
#include <tuple>

namespace rc {

namespace {

// Radiosity at each patch corner: the area-weighted mean of the patches of the same surface that
// share that corner. Interpolating these across each patch gives shading that is smooth between
// patch centres yet never bleeds across a crease (a different surface).
class CornerValues {
 public:
  CornerValues(const Scene& scene, const std::vector<Spectrum>& radiosity) {
    for (std::size_t i = 0; i < scene.patches.size(); ++i) {
      const Patch& p = scene.patches[i];
      const int surface = scene.faces[p.face].surface;
      for (const Vec3& v : {p.tri.v0, p.tri.v1, p.tri.v2}) {
        Sum& s = sums_[key(surface, v)];
        s.weighted += radiosity[i] * p.area;
        s.area += p.area;
      }
    }
  }
  Spectrum at(int surface, const Vec3& v) const {
    const Sum& s = sums_.at(key(surface, v));
    return s.weighted * (1.0 / s.area);
  }

 private:
  struct Sum {
    Spectrum weighted;
    double area = 0;
  };
  using Key = std::tuple<int, double, double, double>;
  static Key key(int surface, const Vec3& v) { return {surface, v.x, v.y, v.z}; }
  std::map<Key, Sum> sums_;
};

struct ScreenVertex {
  double x, y;      // pixel coordinates
  double inv_z;     // 1 / view depth, for perspective-correct interpolation
  Spectrum value;
};

class Projector {
 public:
  Projector(const Camera& c, int width, int height) : width_(width), height_(height) {
    position_ = c.position;
    forward_ = glm::normalize(c.look_at - c.position);
    right_ = glm::normalize(glm::cross(forward_, c.up));
    up_ = glm::cross(right_, forward_);
    tan_half_ = std::tan(c.vertical_fov_deg * M_PI / 360.0);
  }
  // Returns false for points at or behind the eye.
  bool project(const Vec3& p, ScreenVertex& out) const {
    const Vec3 d = p - position_;
    const double z = glm::dot(d, forward_);
    if (z <= 1e-9) return false;
    const double aspect = double(width_) / height_;
    out.x = 0.5 * width_ * (1.0 + glm::dot(d, right_) / (z * tan_half_ * aspect));
    out.y = 0.5 * height_ * (1.0 - glm::dot(d, up_) / (z * tan_half_));
    out.inv_z = 1.0 / z;
    return true;
  }

 private:
  int width_, height_;
  Vec3 position_, forward_, right_, up_;
  double tan_half_ = 1;
};

double edge(const ScreenVertex& a, const ScreenVertex& b, double px, double py) {
  return (b.x - a.x) * (py - a.y) - (b.y - a.y) * (px - a.x);
}

// floor/ceil of a pixel coordinate clamped to [lo, hi] before it becomes an int: a corner just in
// front of the eye projects far outside the picture, beyond what an int holds.
int clamped_floor(double v, int lo, int hi) { return int(std::clamp(std::floor(v), double(lo), double(hi))); }
int clamped_ceil(double v, int lo, int hi) { return int(std::clamp(std::ceil(v), double(lo), double(hi))); }

struct ScreenTriangle {
  ScreenVertex v[3];
  int y0, y1;  // the supersampled rows its bounding box covers (before clipping to a band)
};

// A band of supersampled rows [first_row, first_row + img.height) of the whole picture: every pixel
// gets what it would get in a picture drawn whole (the same sample point, the same triangles in the
// same order).
void rasterise(const ScreenTriangle& t, int first_row, HdrImage& img, std::vector<double>& depth) {
  const ScreenVertex (&v)[3] = t.v;
  const double area = edge(v[0], v[1], v[2].x, v[2].y);
  if (area == 0) return;
  const int x0 = clamped_floor(std::min({v[0].x, v[1].x, v[2].x}), 0, img.width);
  const int x1 = clamped_ceil(std::max({v[0].x, v[1].x, v[2].x}), -1, img.width - 1);
  const int y0 = std::max(first_row, t.y0);
  const int y1 = std::min(first_row + img.height - 1, t.y1);
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      const double px = x + 0.5, py = y + 0.5;
      const double w0 = edge(v[1], v[2], px, py) / area;
      const double w1 = edge(v[2], v[0], px, py) / area;
      const double w2 = 1.0 - w0 - w1;
      if (w0 < 0 || w1 < 0 || w2 < 0) continue;
      const double inv_z = w0 * v[0].inv_z + w1 * v[1].inv_z + w2 * v[2].inv_z;
      const std::size_t i = std::size_t(y - first_row) * img.width + x;
      if (inv_z <= depth[i]) continue;  // something nearer is already there
      depth[i] = inv_z;
      const Spectrum sum = v[0].value * (w0 * v[0].inv_z) + v[1].value * (w1 * v[1].inv_z) +
                           v[2].value * (w2 * v[2].inv_z);
      img.pixels[i] = sum * (1.0 / inv_z);
      img.covered[i] = true;
    }
  }
}

// Averages `big` (a band of supersampled rows) into `out` from row `first_out_row` on.
void downsample_into(const HdrImage& big, int factor, int first_out_row, HdrImage& out) {
  for (int y = 0; y < big.height / factor; ++y) {
    for (int x = 0; x < out.width; ++x) {
      Spectrum sum;
      bool any = false;
      for (int sy = 0; sy < factor; ++sy) {
        for (int sx = 0; sx < factor; ++sx) {
          const std::size_t i = std::size_t(y * factor + sy) * big.width + (x * factor + sx);
          sum += big.pixels[i];
          any = any || big.covered[i];
        }
      }
      out.pixels[std::size_t(first_out_row + y) * out.width + x] = sum * (1.0 / (factor * factor));
      out.covered[std::size_t(first_out_row + y) * out.width + x] = any;
    }
  }
}

double luminance(const Spectrum& s) {
  return kBands == 3 ? 0.2126 * s[0] + 0.7152 * s[1] + 0.0722 * s[2] : s.sum() / kBands;
}

std::uint8_t to_srgb8(double linear) {
  const double c = std::clamp(linear, 0.0, 1.0);
  const double s = c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
  return static_cast<std::uint8_t>(std::lround(s * 255.0));
}

}  // namespace

HdrImage render_radiosity(const Scene& scene, const std::vector<Spectrum>& radiosity,
                          const RenderOptions& options) {
  if (radiosity.size() != scene.patches.size()) throw std::invalid_argument("one radiosity value per patch expected");
  if (options.width <= 0 || options.height <= 0 || options.supersample <= 0) {
    throw std::invalid_argument("image size and supersampling must be positive");
  }
  // A degenerate camera would project nothing (an all-black picture); NaN radiosity would too.
  check_camera(scene.camera);
  for (std::size_t i = 0; i < radiosity.size(); ++i) {
    for (double b : radiosity[i].band) {
      if (!std::isfinite(b)) throw std::invalid_argument("the radiosity of patch " + std::to_string(i) + " is not finite");
    }
  }
  const int ss = options.supersample;
  const int w = options.width * ss, h = options.height * ss;
  const CornerValues corners(scene, radiosity);
  const Projector projector(scene.camera, w, h);
  std::vector<ScreenTriangle> triangles;
  triangles.reserve(scene.patches.size());
  for (const Patch& p : scene.patches) {
    // A two-sided surface's faces lie in one plane (a sheet): only the side facing the camera is
    // drawn, or front and back would fight over every pixel. One-sided faces are drawn either way.
    if (scene.sheets.size_of(p.face) > 1 && !(glm::dot(p.normal, scene.camera.position - p.centre) > 0)) continue;
    const int surface = scene.faces[p.face].surface;
    ScreenTriangle t;
    const Vec3 corner[3] = {p.tri.v0, p.tri.v1, p.tri.v2};
    bool visible = true;
    for (int k = 0; k < 3 && visible; ++k) {
      visible = projector.project(corner[k], t.v[k]);
      t.v[k].value = corners.at(surface, corner[k]);
    }
    if (!visible) continue;  // the scene lies in front of the camera; no clipping
    t.y0 = clamped_floor(std::min({t.v[0].y, t.v[1].y, t.v[2].y}), 0, h);
    t.y1 = clamped_ceil(std::max({t.v[0].y, t.v[1].y, t.v[2].y}), -1, h - 1);
    if (t.y0 <= t.y1) triangles.push_back(t);
  }
  // The supersampled picture is drawn in bands of whole output rows, each at most band_bytes (an
  // 8192-pixel picture drawn whole took 10 GB), and averaged into the output as each is done.
  const std::size_t sample_bytes = sizeof(Spectrum) + sizeof(double) + 1;  // value, depth, covered
  const std::size_t row_bytes = std::size_t(w) * ss * sample_bytes;        // one output row's samples
  const int band_rows = int(std::clamp<std::size_t>(options.band_bytes / row_bytes, 1, std::size_t(options.height)));
  HdrImage out{options.width, options.height, std::vector<Spectrum>(std::size_t(options.width) * options.height),
               std::vector<bool>(std::size_t(options.width) * options.height, false)};
  for (int first = 0; first < options.height; first += band_rows) {
    const int rows = std::min(band_rows, options.height - first) * ss;
    HdrImage band{w, rows, std::vector<Spectrum>(std::size_t(w) * rows), std::vector<bool>(std::size_t(w) * rows, false)};
    std::vector<double> depth(band.pixels.size(), 0.0);
    for (const ScreenTriangle& t : triangles) {
      if (t.y1 >= first * ss && t.y0 < first * ss + rows) rasterise(t, first * ss, band, depth);
    }
    downsample_into(band, ss, first, out);
  }
  return out;
}

namespace {

// The power of two that brings the brightest covered pixel of a dim scene into [1, 2): a scene's
// units are its own (docs/scenes.md), and the tone map's 1e-9 floor below (which keeps black pixels
// out of the logarithm) assumed values near 1. Emission of 1e-10 gave an all-black picture, and
// luminances near the subnormals overflowed the scale. 0 for a scene whose brightest pixel is at
// least 1 (the Cornell Box's units): its picture stays the same, byte for byte.
int dim_scene_exponent(const HdrImage& hdr) {
  double brightest = 0;
  for (std::size_t i = 0; i < hdr.pixels.size(); ++i)
    if (hdr.covered[i]) brightest = std::max(brightest, luminance(hdr.pixels[i]));
  if (!(brightest > 0) || brightest >= 1) return 0;
  return -std::ilogb(brightest);  // exact: a power of two changes no digit of a normal double
}

}  // namespace

// Photographic tone mapping (Reinhard et al. 2002, global operator): scale so the log-average
// luminance lands on `key`, then compress highlights with L / (1 + L) so the light stays white.
// Pixels are first scaled by the power of two of dim_scene_exponent: any unit system gives a picture.
RgbImage tone_map(const HdrImage& hdr, double key) {
  const int exponent = dim_scene_exponent(hdr);
  auto pixel = [&](std::size_t i) {
    Spectrum p = hdr.pixels[i];
    if (exponent != 0)
      for (double& b : p.band) b = std::ldexp(b, exponent);
    return p;
  };
  double log_sum = 0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < hdr.pixels.size(); ++i) {
    if (!hdr.covered[i]) continue;
    log_sum += std::log(1e-9 + luminance(pixel(i)));
    ++count;
  }
  const double log_average = count ? std::exp(log_sum / count) : 1.0;
  const double scale = key / log_average;
  RgbImage out{hdr.width, hdr.height, std::vector<std::uint8_t>(hdr.pixels.size() * 3, 0)};
  for (std::size_t i = 0; i < hdr.pixels.size(); ++i) {
    const Spectrum c = pixel(i) * scale;
    const double l = luminance(c);
    const double compress = 1.0 / (1.0 + l);
    for (std::size_t b = 0; b < 3 && b < kBands; ++b) out.pixels[i * 3 + b] = to_srgb8(c[b] * compress);
  }
  return out;
}

std::string dark_picture_warning(const RgbImage& image) {
  const std::size_t pixels = std::size_t(image.width) * std::size_t(image.height);
  if (pixels == 0 || image.pixels.size() < 3 * pixels) return "";
  std::size_t dark = 0;
  for (std::size_t i = 0; i < pixels; ++i) {
    const std::uint8_t* p = &image.pixels[3 * i];
    if (std::max({p[0], p[1], p[2]}) <= kDarkPixelLevel) ++dark;
  }
  const double share = double(dark) / double(pixels);
  if (share < kDarkPictureShare) return "";
  char text[320];
  std::snprintf(text, sizeof text,
                "the picture is dark: %.1f%% of its pixels are black (no channel above %d of 255); the camera may "
                "look past the scene or from behind a wall (a scene file's `camera` line, a composition's `camera` "
                "key; without one the scene's bounds are framed), or nothing it sees is lit",
                100.0 * share, kDarkPixelLevel);
  return text;
}

}  // namespace rc
