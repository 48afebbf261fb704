#include "scenes/cornell_box.h"

#include <stdexcept>

#include "scenes/scene_builder.h"

namespace rc {

namespace {

constexpr int kSamples = 76;
constexpr double kFirstNm = 400.0;
constexpr double kStepNm = 4.0;

// Reflectance spectra exactly as published (400-700 nm every 4 nm).
const double kWhite[kSamples] = {
    0.343, 0.445, 0.551, 0.624, 0.665, 0.687, 0.708, 0.723, 0.715, 0.710, 0.745, 0.758, 0.739,
    0.767, 0.777, 0.765, 0.751, 0.745, 0.748, 0.729, 0.745, 0.757, 0.753, 0.750, 0.746, 0.747,
    0.735, 0.732, 0.739, 0.734, 0.725, 0.721, 0.733, 0.725, 0.732, 0.743, 0.744, 0.748, 0.728,
    0.716, 0.733, 0.726, 0.713, 0.740, 0.754, 0.764, 0.752, 0.736, 0.734, 0.741, 0.740, 0.732,
    0.745, 0.755, 0.751, 0.744, 0.731, 0.733, 0.744, 0.731, 0.712, 0.708, 0.729, 0.730, 0.727,
    0.707, 0.703, 0.729, 0.750, 0.760, 0.751, 0.739, 0.724, 0.730, 0.740, 0.737};
const double kGreen[kSamples] = {
    0.092, 0.096, 0.098, 0.097, 0.098, 0.095, 0.095, 0.097, 0.095, 0.094, 0.097, 0.098, 0.096,
    0.101, 0.103, 0.104, 0.107, 0.109, 0.112, 0.115, 0.125, 0.140, 0.160, 0.187, 0.229, 0.285,
    0.343, 0.390, 0.435, 0.464, 0.472, 0.476, 0.481, 0.462, 0.447, 0.441, 0.426, 0.406, 0.373,
    0.347, 0.337, 0.314, 0.285, 0.277, 0.266, 0.250, 0.230, 0.207, 0.186, 0.171, 0.160, 0.148,
    0.141, 0.136, 0.130, 0.126, 0.123, 0.121, 0.122, 0.119, 0.114, 0.115, 0.117, 0.117, 0.118,
    0.120, 0.122, 0.128, 0.132, 0.139, 0.144, 0.146, 0.150, 0.152, 0.157, 0.159};
const double kRed[kSamples] = {
    0.040, 0.046, 0.048, 0.053, 0.049, 0.050, 0.053, 0.055, 0.057, 0.056, 0.059, 0.057, 0.061,
    0.061, 0.060, 0.062, 0.062, 0.062, 0.061, 0.062, 0.060, 0.059, 0.057, 0.058, 0.058, 0.058,
    0.056, 0.055, 0.056, 0.059, 0.057, 0.055, 0.059, 0.059, 0.058, 0.059, 0.061, 0.061, 0.063,
    0.063, 0.067, 0.068, 0.072, 0.080, 0.090, 0.099, 0.124, 0.154, 0.192, 0.255, 0.287, 0.349,
    0.402, 0.443, 0.487, 0.513, 0.558, 0.584, 0.620, 0.606, 0.609, 0.651, 0.612, 0.610, 0.650,
    0.638, 0.627, 0.620, 0.630, 0.628, 0.642, 0.639, 0.657, 0.639, 0.635, 0.642};

// Mitsuba's cbox gives the light a diffuse reflectance of 0.78; the source data gives none.
constexpr double kLightReflectance = 0.78;

SampledSpectrum from_table(const double (&table)[kSamples]) {
  return {std::vector<double>(table, table + kSamples)};
}

double wavelength(int i) { return kFirstNm + kStepNm * i; }

struct QuadSpec {
  const char* name;
  const char* material;
  double v[4][3];
};

// Verbatim from the Cornell data (mm), except the ceiling, which is cut around the light below.
const QuadSpec kQuads[] = {
    {"floor", "white", {{552.8, 0, 0}, {0, 0, 0}, {0, 0, 559.2}, {549.6, 0, 559.2}}},
    {"light", "light", {{343.0, 548.8, 227.0}, {343.0, 548.8, 332.0}, {213.0, 548.8, 332.0}, {213.0, 548.8, 227.0}}},
    {"back wall", "white", {{549.6, 0, 559.2}, {0, 0, 559.2}, {0, 548.8, 559.2}, {556.0, 548.8, 559.2}}},
    {"right wall", "green", {{0, 0, 559.2}, {0, 0, 0}, {0, 548.8, 0}, {0, 548.8, 559.2}}},
    {"left wall", "red", {{552.8, 0, 0}, {549.6, 0, 559.2}, {556.0, 548.8, 559.2}, {556.0, 548.8, 0}}},
    {"short block top", "white", {{130, 165, 65}, {82, 165, 225}, {240, 165, 272}, {290, 165, 114}}},
    {"short block side", "white", {{290, 0, 114}, {290, 165, 114}, {240, 165, 272}, {240, 0, 272}}},
    {"short block side", "white", {{130, 0, 65}, {130, 165, 65}, {290, 165, 114}, {290, 0, 114}}},
    {"short block side", "white", {{82, 0, 225}, {82, 165, 225}, {130, 165, 65}, {130, 0, 65}}},
    {"short block side", "white", {{240, 0, 272}, {240, 165, 272}, {82, 165, 225}, {82, 0, 225}}},
    {"tall block top", "white", {{423, 330, 247}, {265, 330, 296}, {314, 330, 456}, {472, 330, 406}}},
    {"tall block side", "white", {{423, 0, 247}, {423, 330, 247}, {472, 330, 406}, {472, 0, 406}}},
    {"tall block side", "white", {{472, 0, 406}, {472, 330, 406}, {314, 330, 456}, {314, 0, 456}}},
    {"tall block side", "white", {{314, 0, 456}, {314, 330, 456}, {265, 330, 296}, {265, 0, 296}}},
    {"tall block side", "white", {{265, 0, 296}, {265, 330, 296}, {423, 330, 247}, {423, 0, 247}}},
};

// The light is coplanar with the ceiling and overlaps it. We cut the ceiling around the light
// (as the real box has the light in a hole): exact at every fixed-point width, unlike lowering it.
constexpr double kCeilingY = 548.8;
constexpr double kCeilingX1 = 556.0, kCeilingZ1 = 559.2;
constexpr double kLightX0 = 213.0, kLightX1 = 343.0, kLightZ0 = 227.0, kLightZ1 = 332.0;

// A ceiling rectangle facing down, wound like the published ceiling quad.
std::vector<Vec3> ceiling_rect(double x0, double x1, double z0, double z1) {
  return {{x1, kCeilingY, z0}, {x1, kCeilingY, z1}, {x0, kCeilingY, z1}, {x0, kCeilingY, z0}};
}

}  // namespace

Spectrum to_rgb_band_means(const SampledSpectrum& s) {
  if (s.values.size() != kSamples) throw std::invalid_argument("expected 76 spectral samples");
  Spectrum sum, count;
  for (int i = 0; i < kSamples; ++i) {
    const double nm = wavelength(i);
    const std::size_t band = nm >= 600.0 ? 0 : nm >= 500.0 ? 1 : 2;  // R, G, B
    sum[band] += s.values[i];
    count[band] += 1.0;
  }
  Spectrum mean;
  for (std::size_t b = 0; b < kBands; ++b) mean[b] = sum[b] / count[b];
  return mean;
}

SampledSpectrum cornell_white() { return from_table(kWhite); }
SampledSpectrum cornell_red() { return from_table(kRed); }
SampledSpectrum cornell_green() { return from_table(kGreen); }

SampledSpectrum cornell_light_emission() {
  const double knots_nm[] = {400, 500, 600, 700};
  const double knots[] = {0.0, 8.0, 15.6, 18.4};
  SampledSpectrum s;
  for (int i = 0; i < kSamples; ++i) {
    const double nm = wavelength(i);
    const int k = nm >= 600 ? 2 : nm >= 500 ? 1 : 0;
    const double f = (nm - knots_nm[k]) / 100.0;
    s.values.push_back(knots[k] + f * (knots[k + 1] - knots[k]));
  }
  return s;
}

Scene cornell_box() {
  SceneBuilder builder("cornell-box");
  const Spectrum black = Spectrum::uniform(0.0);
  builder.add_material({"white", to_rgb_band_means(cornell_white()), black});
  builder.add_material({"red", to_rgb_band_means(cornell_red()), black});
  builder.add_material({"green", to_rgb_band_means(cornell_green()), black});
  builder.add_material({"light", Spectrum::uniform(kLightReflectance),
                        to_rgb_band_means(cornell_light_emission())});

  for (const QuadSpec& q : kQuads) {
    std::vector<Vec3> v;
    for (const auto& p : q.v) v.emplace_back(p[0], p[1], p[2]);
    builder.add_surface(q.name, builder.find_material(q.material), v, "cornell-box");
  }
  const int white = builder.find_material("white");
  builder.add_surface("ceiling", white, ceiling_rect(0, kCeilingX1, 0, kLightZ0), "cornell-box");
  builder.add_surface("ceiling", white, ceiling_rect(0, kCeilingX1, kLightZ1, kCeilingZ1), "cornell-box");
  builder.add_surface("ceiling", white, ceiling_rect(kLightX1, kCeilingX1, kLightZ0, kLightZ1), "cornell-box");
  builder.add_surface("ceiling", white, ceiling_rect(0, kLightX0, kLightZ0, kLightZ1), "cornell-box");
  builder.set_camera(Camera{});
  return builder.build();
}

}  // namespace rc
