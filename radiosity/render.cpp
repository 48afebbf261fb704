#include "radiosity/render.h"

#include <algorithm>
#include <cmath>
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

void rasterise(const ScreenVertex (&v)[3], HdrImage& img, std::vector<double>& depth) {
  const double area = edge(v[0], v[1], v[2].x, v[2].y);
  if (area == 0) return;
  const int x0 = std::max(0, int(std::floor(std::min({v[0].x, v[1].x, v[2].x}))));
  const int x1 = std::min(img.width - 1, int(std::ceil(std::max({v[0].x, v[1].x, v[2].x}))));
  const int y0 = std::max(0, int(std::floor(std::min({v[0].y, v[1].y, v[2].y}))));
  const int y1 = std::min(img.height - 1, int(std::ceil(std::max({v[0].y, v[1].y, v[2].y}))));
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      const double px = x + 0.5, py = y + 0.5;
      const double w0 = edge(v[1], v[2], px, py) / area;
      const double w1 = edge(v[2], v[0], px, py) / area;
      const double w2 = 1.0 - w0 - w1;
      if (w0 < 0 || w1 < 0 || w2 < 0) continue;
      const double inv_z = w0 * v[0].inv_z + w1 * v[1].inv_z + w2 * v[2].inv_z;
      const std::size_t i = std::size_t(y) * img.width + x;
      if (inv_z <= depth[i]) continue;  // something nearer is already there
      depth[i] = inv_z;
      const Spectrum sum = v[0].value * (w0 * v[0].inv_z) + v[1].value * (w1 * v[1].inv_z) +
                           v[2].value * (w2 * v[2].inv_z);
      img.pixels[i] = sum * (1.0 / inv_z);
      img.covered[i] = true;
    }
  }
}

HdrImage downsample(const HdrImage& big, int factor) {
  HdrImage out{big.width / factor, big.height / factor, {}, {}};
  out.pixels.assign(std::size_t(out.width) * out.height, Spectrum{});
  out.covered.assign(out.pixels.size(), false);
  for (int y = 0; y < out.height; ++y) {
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
      out.pixels[std::size_t(y) * out.width + x] = sum * (1.0 / (factor * factor));
      out.covered[std::size_t(y) * out.width + x] = any;
    }
  }
  return out;
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
  const int w = options.width * options.supersample, h = options.height * options.supersample;
  HdrImage big{w, h, std::vector<Spectrum>(std::size_t(w) * h), std::vector<bool>(std::size_t(w) * h, false)};
  std::vector<double> depth(big.pixels.size(), 0.0);
  const CornerValues corners(scene, radiosity);
  const Projector projector(scene.camera, w, h);
  for (const Patch& p : scene.patches) {
    const int surface = scene.faces[p.face].surface;
    ScreenVertex v[3];
    const Vec3 corner[3] = {p.tri.v0, p.tri.v1, p.tri.v2};
    bool visible = true;
    for (int k = 0; k < 3 && visible; ++k) {
      visible = projector.project(corner[k], v[k]);
      v[k].value = corners.at(surface, corner[k]);
    }
    if (visible) rasterise(v, big, depth);  // the scene lies in front of the camera; no clipping
  }
  return downsample(big, options.supersample);
}

// Photographic tone mapping (Reinhard et al. 2002, global operator): scale so the log-average
// luminance lands on `key`, then compress highlights with L / (1 + L) so the light stays white.
RgbImage tone_map(const HdrImage& hdr, double key) {
  double log_sum = 0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < hdr.pixels.size(); ++i) {
    if (!hdr.covered[i]) continue;
    log_sum += std::log(1e-9 + luminance(hdr.pixels[i]));
    ++count;
  }
  const double log_average = count ? std::exp(log_sum / count) : 1.0;
  const double scale = key / log_average;
  RgbImage out{hdr.width, hdr.height, std::vector<std::uint8_t>(hdr.pixels.size() * 3, 0)};
  for (std::size_t i = 0; i < hdr.pixels.size(); ++i) {
    const Spectrum c = hdr.pixels[i] * scale;
    const double l = luminance(c);
    const double compress = 1.0 / (1.0 + l);
    for (std::size_t b = 0; b < 3 && b < kBands; ++b) out.pixels[i * 3 + b] = to_srgb8(c[b] * compress);
  }
  return out;
}

}  // namespace rc
