#include "host_sw/radiosity/receiver_sweep.h"

#include <algorithm>
#include <cmath>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "host_sw/radiosity/radiosity.h"

namespace rc {

PatchColumns::PatchColumns(const Scene& scene) {
  const std::size_t n = scene.patches.size();
  for (auto* column : {&cx, &cy, &cz, &nx, &ny, &nz, &area}) column->resize(n);
  sheet_value.resize(n);
  centre.resize(n);
  face.resize(n);
  reflectance.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Patch& p = scene.patches[i];
    cx[i] = p.centre.x, cy[i] = p.centre.y, cz[i] = p.centre.z;
    nx[i] = p.normal.x, ny[i] = p.normal.y, nz[i] = p.normal.z;
    area[i] = p.area;
    sheet_value[i] = scene.sheets.first(p.face);
    centre[i] = p.centre;
    face[i] = p.face;
    reflectance[i] = scene.material_of(p).reflectance;
  }
}

namespace {

// The shooter's values, shared by every receiver.
struct Shooter {
  double x, y, z, nx, ny, nz, area;
  double sheet;  // as a double (exact: a face index), compared with the receivers' column
  double disc;   // the disc rule's + A in the denominator; 0 for the point rule
  double point;  // 1, or 0 for the analytic rule (the caller integrates)
};

// One receiver, with the operations of pair_geometry (glm::dot sums x, y, z left to right),
// ProgressiveRadiosity's sheet and coincidence rule and form_factor, operation for operation.
void sweep_one(const PatchColumns& p, const Shooter& s, std::size_t j, ReceiverSweep& out) {
  const double dx = p.cx[j] - s.x, dy = p.cy[j] - s.y, dz = p.cz[j] - s.z;
  const double r2 = dx * dx + dy * dy + dz * dz;
  const bool none = p.sheet_value[j] == s.sheet || r2 == 0 ||
                    r2 < kCoincidentDistance * kCoincidentDistance * std::max(s.area, p.area[j]);
  const double r = std::sqrt(r2);
  const double cs = none ? 0.0 : (s.nx * dx + s.ny * dy + s.nz * dz) / r;
  const double cr = none ? 0.0 : -(p.nx[j] * dx + p.ny[j] * dy + p.nz[j] * dz) / r;
  const double g_r2 = none ? 0.0 : r2;
  const bool exchange = cs > PairGeometry::kMinCosine && cr > PairGeometry::kMinCosine;
  out.cos_shooter[j] = cs;
  out.cos_receiver[j] = cr;
  out.distance_squared[j] = g_r2;
  out.form_factor[j] = exchange ? cs * cr * s.area / (glm::pi<double>() * g_r2 + s.disc) * s.point : 0.0;
  out.exchanges[j] = exchange;
}

#if defined(__SSE2__)
// Two receivers at a time, the same operations as sweep_one in the same order, every one run for
// both lanes (a division by a zero distance included: its lane is then masked to 0), so no branch.
// Written with SSE2 intrinsics (every x86-64 has them): separate multiplies and adds, never fused.
void sweep_pairs(const PatchColumns& p, const Shooter& s, std::size_t n, ReceiverSweep& out) {
  const __m128d sx = _mm_set1_pd(s.x), sy = _mm_set1_pd(s.y), sz = _mm_set1_pd(s.z);
  const __m128d snx = _mm_set1_pd(s.nx), sny = _mm_set1_pd(s.ny), snz = _mm_set1_pd(s.nz);
  const __m128d area = _mm_set1_pd(s.area), sheet = _mm_set1_pd(s.sheet), zero = _mm_setzero_pd();
  const __m128d coincident = _mm_set1_pd(kCoincidentDistance * kCoincidentDistance);
  const __m128d pi = _mm_set1_pd(glm::pi<double>()), disc = _mm_set1_pd(s.disc), point = _mm_set1_pd(s.point);
  const __m128d min_cosine = _mm_set1_pd(PairGeometry::kMinCosine), sign = _mm_set1_pd(-0.0);
  const auto dot = [](__m128d ax, __m128d ay, __m128d az, __m128d bx, __m128d by, __m128d bz) {
    return _mm_add_pd(_mm_add_pd(_mm_mul_pd(ax, bx), _mm_mul_pd(ay, by)), _mm_mul_pd(az, bz));
  };
  for (std::size_t j = 0; j + 2 <= n; j += 2) {
    const __m128d dx = _mm_sub_pd(_mm_loadu_pd(&p.cx[j]), sx);
    const __m128d dy = _mm_sub_pd(_mm_loadu_pd(&p.cy[j]), sy);
    const __m128d dz = _mm_sub_pd(_mm_loadu_pd(&p.cz[j]), sz);
    const __m128d r2 = dot(dx, dy, dz, dx, dy, dz);
    // std::max(a, b) is b where a < b, else a: the same value for positive areas.
    const __m128d size_squared = _mm_max_pd(_mm_loadu_pd(&p.area[j]), area);
    const __m128d none = _mm_or_pd(_mm_or_pd(_mm_cmpeq_pd(_mm_loadu_pd(&p.sheet_value[j]), sheet), _mm_cmpeq_pd(r2, zero)),
                                   _mm_cmplt_pd(r2, _mm_mul_pd(coincident, size_squared)));
    const __m128d r = _mm_sqrt_pd(r2);
    const __m128d cs = _mm_andnot_pd(none, _mm_div_pd(dot(snx, sny, snz, dx, dy, dz), r));
    const __m128d receiver_dot = dot(_mm_loadu_pd(&p.nx[j]), _mm_loadu_pd(&p.ny[j]), _mm_loadu_pd(&p.nz[j]), dx, dy, dz);
    const __m128d cr = _mm_andnot_pd(none, _mm_div_pd(_mm_xor_pd(receiver_dot, sign), r));
    const __m128d g_r2 = _mm_andnot_pd(none, r2);
    const __m128d exchange = _mm_and_pd(_mm_cmpgt_pd(cs, min_cosine), _mm_cmpgt_pd(cr, min_cosine));
    const __m128d f = _mm_div_pd(_mm_mul_pd(_mm_mul_pd(cs, cr), area), _mm_add_pd(_mm_mul_pd(pi, g_r2), disc));
    _mm_storeu_pd(&out.cos_shooter[j], cs);
    _mm_storeu_pd(&out.cos_receiver[j], cr);
    _mm_storeu_pd(&out.distance_squared[j], g_r2);
    _mm_storeu_pd(&out.form_factor[j], _mm_and_pd(exchange, _mm_mul_pd(f, point)));
    const int mask = _mm_movemask_pd(exchange);
    out.exchanges[j] = static_cast<std::uint8_t>(mask & 1);
    out.exchanges[j + 1] = static_cast<std::uint8_t>(mask >> 1);
  }
}
#endif

}  // namespace

void sweep_receivers(const PatchColumns& patches, int shooter, FormFactorKind kind, ReceiverSweep& out) {
  const std::size_t n = patches.size();
  for (auto* column : {&out.cos_shooter, &out.cos_receiver, &out.distance_squared, &out.form_factor}) column->resize(n);
  out.exchanges.resize(n);
  const std::size_t at = static_cast<std::size_t>(shooter);
  const Shooter s{patches.cx[at], patches.cy[at], patches.cz[at], patches.nx[at], patches.ny[at], patches.nz[at],
                  patches.area[at], patches.sheet_value[at], kind == FormFactorKind::Disc ? patches.area[at] : 0.0,
                  kind == FormFactorKind::Analytic ? 0.0 : 1.0};
  std::size_t j = 0;
#if defined(__SSE2__)
  sweep_pairs(patches, s, n, out);
  j = n - n % 2;
#endif
  for (; j < n; ++j) sweep_one(patches, s, j, out);
  out.exchanges[static_cast<std::size_t>(shooter)] = 0;  // a patch does not shoot at itself
  out.form_factor[static_cast<std::size_t>(shooter)] = 0;
}

}  // namespace rc
