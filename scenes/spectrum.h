// Colour carried by radiosity: a fixed number of wavelength bands. Radiosity is linear per band and
// visibility does not depend on the band, so more bands cost little; change kBands (and the
// material conversion in cornell_box.cpp) to carry more.
#pragma once

#include <array>
#include <cstddef>

namespace rc {

constexpr std::size_t kBands = 3;  // R, G, B: band means over 600-700, 500-600, 400-500 nm

struct Spectrum {
  std::array<double, kBands> band{};

  static Spectrum uniform(double value) {
    Spectrum s;
    s.band.fill(value);
    return s;
  }
  double& operator[](std::size_t i) { return band[i]; }
  double operator[](std::size_t i) const { return band[i]; }
  double sum() const {
    double total = 0;
    for (double b : band) total += b;
    return total;
  }
  double max() const {
    double m = band[0];
    for (double b : band) m = b > m ? b : m;
    return m;
  }
  bool is_black() const { return max() <= 0.0; }

  Spectrum& operator+=(const Spectrum& o) {
    for (std::size_t i = 0; i < kBands; ++i) band[i] += o.band[i];
    return *this;
  }
  friend Spectrum operator+(Spectrum a, const Spectrum& b) { return a += b; }
  friend Spectrum operator*(Spectrum a, const Spectrum& b) {
    for (std::size_t i = 0; i < kBands; ++i) a.band[i] *= b.band[i];
    return a;
  }
  friend Spectrum operator*(Spectrum a, double k) {
    for (double& v : a.band) v *= k;
    return a;
  }
  friend Spectrum operator*(double k, Spectrum a) { return a * k; }
};

}  // namespace rc
