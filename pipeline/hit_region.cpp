#include "pipeline/hit_region.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "pipeline/fixed_mt.h"
#include "pipeline/mt_core.h"

namespace rc::pipeline {

namespace {

// What the pipeline computes for one face and one start before it sees any direction: tvec,
// qvec and t, from the pipeline's own stage templates (mt_core.h) so that they are its exact
// bits. A zero direction stands in for the direction, which none of the three depends on.
struct FaceStartValues {
  FixedVec3 tvec, qvec;
  std::int64_t t;
};

[[gnu::always_inline]] inline FaceStartValues face_start_values(const FaceRecord& face, const FixedVec3& start, FracBits bits) {
  const FixedVec3 none{0, 0, 0};
  NoProbe probe;
  const Stage1Values<std::int64_t> s1 = stage1(face.v0, face.edge2, start, none, bits, probe);
  const Stage2Values<std::int64_t> s2 = stage2(face.edge1, s1, bits, probe);
  const Stage3Values<std::int64_t> s3 = stage3(face.edge2, none, s1, s2, bits, probe);
  return {s1.tvec, s2.qvec, s3.t};
}

// a x b without truncation. Components stay below 2 * (2^31)^2 = 2^63, so 64 bits hold them.
FixedVec3 exact_cross(const FixedVec3& a, const FixedVec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

std::int64_t l1_norm(const FixedVec3& v) { return std::llabs(v.x) + std::llabs(v.y) + std::llabs(v.z); }

// The largest amount a truncation floor((w * k) / M) can drop, in units of 1/M, over every
// integer k: w * k mod M is a multiple of gcd(w, M), so at most M - gcd(w, M); nothing when w is 0
// (gcd(0, M) = M). M = 2^bits, so gcd(w, M) = 2^min(trailing zeros of w, bits).
std::int64_t max_floor_loss(std::int64_t w, FracBits bits) {
  if (w == 0) return 0;
  const int zeros = std::min(__builtin_ctzll(static_cast<unsigned long long>(w)), static_cast<int>(bits));
  return (std::int64_t{1} << bits) - (std::int64_t{1} << zeros);
}

std::int64_t floor_loss(const FixedVec3& w, FracBits bits) {
  return max_floor_loss(w.x, bits) + max_floor_loss(w.y, bits) + max_floor_loss(w.z, bits);
}

// sum_i w_i * (M pvec_i - (d x e2)_i) over the face's pvec errors. |w_i| < 2^32 and the losses are
// below 2^31, so each product fits 64 bits; the sums are taken in 128.
ErrorRange pvec_part(const FaceErrorTerms& f, std::int64_t w0, std::int64_t w1, std::int64_t w2) {
  const std::int64_t w[3] = {w0, w1, w2};
  ErrorRange r;
  for (int i = 0; i < 3; ++i) {
    const bool negative = w[i] < 0;
    r.lo += Wide(w[i] * (negative ? f.pvec_hi[i] : f.pvec_lo[i]));
    r.hi += Wide(w[i] * (negative ? f.pvec_lo[i] : f.pvec_hi[i]));
  }
  return r;
}

// Everything the four conditions are built from (docs/fast-visibility.md, "The four conditions").
// Unit: 2^-bits, so M = 2^bits is "1.0".
struct ConditionInputs {
  bool empty;
  int sign;             // s = sign(t): the sign det must have for a hit
  std::int64_t abs_t;
  FixedVec3 n_u;        // u   = d . n_u / M^2 + error    (n_u = edge2 x tvec)
  FixedVec3 qvec;       // v   = d . qvec / M + error
  std::int64_t l1_tvec;  // bounds the errors below (for the rounding margins)
  // M^2 u - d.n_u, M v - d.qvec and M^2 (det - u - v) - d.W over every d (det's: FaceErrorTerms).
  ErrorRange u, v, w;
};

// The start's share of the errors takes every floor at its worst (the table's bounds): the
// component-wise form pays only for det, whose terms depend on the face alone (FaceErrorTerms,
// computed once per face). Measured with bench_visibility at 7 bits: component-wise u, v and W
// too ran 151.9 kernel tests per segment instead of 152.2, in the same time.
[[gnu::always_inline]] inline ConditionInputs condition_inputs(const FaceRecord& face, const FaceErrorTerms& terms, const FixedVec3& start,
                                 FracBits bits) {
  const FaceStartValues f = face_start_values(face, start, bits);
  ConditionInputs in{};
  in.empty = f.t == 0;
  in.sign = f.t > 0 ? 1 : -1;
  in.abs_t = std::llabs(f.t);
  if (in.empty) return in;
  in.n_u = exact_cross(face.edge2, f.tvec);
  in.qvec = f.qvec;
  in.l1_tvec = l1_norm(f.tvec);
  const Wide m = Wide{1} << bits, m1 = m - 1, tv = in.l1_tvec;
  in.u = {-m1 * tv - 3 * m1 * m, m1 * tv};
  in.v = {-3 * m1, 0};
  // M^2 (det - u - v) - d.W = det's error - u's error - M (v's error).
  in.w = {terms.det.lo - m1 * tv, terms.det.hi + m1 * tv + 6 * m1 * m};
  return in;
}

// a if `first`, else b, without a branch (float and double; other types as they are): which one
// wins follows the sign of t and the rounding of a threshold, which no predictor can guess, and a
// mispredicted branch costs more than computing both.
template <class Num>
Num select(bool first, Num a, Num b) {
  return first ? a : b;
}

template <class Bits, class Num>
Num select_bits(bool first, Num a, Num b) {
  Bits x, y;
  std::memcpy(&x, &a, sizeof x);
  std::memcpy(&y, &b, sizeof y);
  const Bits mask = Bits{0} - static_cast<Bits>(first);
  const Bits r = (x & mask) | (y & ~mask);
  Num out;
  std::memcpy(&out, &r, sizeof out);
  return out;
}

template <>
float select(bool first, float a, float b) {
  return select_bits<std::uint32_t>(first, a, b);
}

template <>
double select(bool first, double a, double b) {
  return select_bits<std::uint64_t>(first, a, b);
}

template <class Num>
struct Thresholds {
  Num c[4];
};

// The four thresholds c[k] of a[k] . d >= c[k], scaled so that a[k] are integer vectors:
// conditions 0, 1 and 3 are multiplied by M^2, condition 2 by M. s * X >= target needs
// s * (d . n_X + error) >= target: with s = +1 the error helps by at most its upper end, with
// s = -1 by minus its lower end.
template <class Num>
Thresholds<Num> thresholds(const FaceErrorTerms& terms, const ConditionInputs& in, Num m) {
  const bool pos = in.sign > 0;
  // Most errors fit 64 bits; converting those from there avoids a slow 128-bit conversion.
  const auto num = [](Wide v) {
    const bool fits = v >= Wide(INT64_MIN) && v <= Wide(INT64_MAX);
    return fits ? Num(static_cast<std::int64_t>(v)) : Num(v);
  };
  const auto c = [&](Num target, const ErrorRange& e) { return target - select<Num>(pos, num(e.hi), -num(e.lo)); };
  Thresholds<Num> r;
  r.c[0] = c(m * m * Num(in.abs_t + 1), terms.det);  // s*det >= |t| + 1
  r.c[1] = c(m * m, in.u);                         // s*u >= 1
  r.c[2] = c(m, in.v);                             // s*v >= 1
  r.c[3] = c(m * m, in.w);                         // s*(det - u - v) >= 1
  return r;
}

}  // namespace

FaceErrorTerms face_error_terms(const FaceRecord& face, FracBits bits) {
  FaceErrorTerms t;
  t.n_det = exact_cross(face.edge2, face.edge1);
  t.l1_edge1 = l1_norm(face.edge1);
  // cross(d, e2): x = d.y e2.z - d.z e2.y, y = d.z e2.x - d.x e2.z, z = d.x e2.y - d.y e2.x, each a
  // difference of two floors: M pvec_i - (d x e2)_i lies in [-loss(first factor), loss(second)].
  const FixedVec3& e2 = face.edge2;
  const std::int64_t loss[3] = {max_floor_loss(e2.x, bits), max_floor_loss(e2.y, bits), max_floor_loss(e2.z, bits)};
  t.pvec_lo[0] = -loss[2], t.pvec_lo[1] = -loss[0], t.pvec_lo[2] = -loss[1];
  t.pvec_hi[0] = loss[1], t.pvec_hi[1] = loss[2], t.pvec_hi[2] = loss[0];
  t.loss_det = floor_loss(face.edge1, bits);
  const ErrorRange p_det = pvec_part(t, face.edge1.x, face.edge1.y, face.edge1.z);
  t.det = {p_det.lo - (Wide{1} << bits) * t.loss_det, p_det.hi};
  return t;
}

ExactHitConditions exact_hit_conditions(const FaceRecord& face, const FixedVec3& start, FracBits bits) {
  const FaceErrorTerms terms = face_error_terms(face, bits);
  const ConditionInputs in = condition_inputs(face, terms, start, bits);
  ExactHitConditions r;
  r.empty = in.empty;
  const __int128 m = __int128{1} << bits, s = in.sign;
  const auto wide = [](std::int64_t v) { return static_cast<__int128>(v); };
  if (r.empty) return r;
  const std::int64_t det_c[3] = {terms.n_det.x, terms.n_det.y, terms.n_det.z};
  const std::int64_t u_c[3] = {in.n_u.x, in.n_u.y, in.n_u.z};
  const std::int64_t q_c[3] = {in.qvec.x, in.qvec.y, in.qvec.z};
  for (int i = 0; i < 3; ++i) {
    r.a[0][i] = s * wide(det_c[i]);
    r.a[1][i] = s * wide(u_c[i]);
    r.a[2][i] = s * wide(q_c[i]);
    r.a[3][i] = s * (wide(det_c[i]) - wide(u_c[i]) - m * wide(q_c[i]));
  }
  const Thresholds<__int128> c = thresholds<__int128>(terms, in, m);
  for (int k = 0; k < 4; ++k) r.c[k] = c.c[k];
  return r;
}

bool ExactHitConditions::allows(const FixedVec3& d) const {
  if (empty) return false;
  for (int k = 0; k < 4; ++k) {
    if (a[k][0] * d.x + a[k][1] * d.y + a[k][2] * d.z < c[k]) return false;
  }
  return true;
}

namespace {

// A float not above x. If rounding to nearest went up, x - |x| 2^-23 lies at least one float
// spacing below x, and rounding it moves it by at most half a spacing.
float round_down(double x) {
  const float f = static_cast<float>(x);
  return select<float>(static_cast<double>(f) <= x, f, static_cast<float>(x - std::fabs(x) * 0x1p-23));
}

}  // namespace

// The double version. Every quantity below is an integer of at most about 2^98; converting and
// combining them in double rounds each step by a relative 2^-53. The sum of all those roundings,
// in computing a[k], c[k], the threshold and later the reach of a box, is below
// 20 * 2^-53 * G[k], where G[k] = M * sum_i mag[k][i] + cmag[k] bounds every term involved
// (coordinates are below M). Lowering the threshold by 2^-44 * G[k], far more than that, keeps
// the double test conservative; at 31 bits it costs under 1/1000 of an LSB of tightness.
HitRegion::HitRegion(const FaceRecord& face, const FixedVec3& start, FracBits bits)
    : HitRegion(face, face_error_terms(face, bits), start, bits) {}

HitRegion::HitRegion(const FaceRecord& face, const FaceErrorTerms& terms, const FixedVec3& start, FracBits bits) {
  const ConditionInputs in = condition_inputs(face, terms, start, bits);
  empty_ = in.empty;
  if (in.empty) {  // nothing passes: zero planes with infinite thresholds
    for (int k = 0; k < 4; ++k) {
      ax_[k] = ay_[k] = az_[k] = 0;
      threshold_[k] = std::numeric_limits<double>::infinity();
      threshold_float_[k] = std::numeric_limits<float>::infinity();
      for (int i = 0; i < 3; ++i) upper_float_[k][i] = lower_float_[k][i] = 0;
    }
    return;
  }
  const double m = static_cast<double>(std::int64_t{1} << bits), s = in.sign;
  const double det_c[3] = {double(terms.n_det.x), double(terms.n_det.y), double(terms.n_det.z)};
  const double u_c[3] = {double(in.n_u.x), double(in.n_u.y), double(in.n_u.z)};
  const double q_c[3] = {double(in.qvec.x), double(in.qvec.y), double(in.qvec.z)};
  double a[4][3], mag[4] = {0, 0, 0, 0};
  for (int i = 0; i < 3; ++i) {
    a[0][i] = s * det_c[i];
    a[1][i] = s * u_c[i];
    a[2][i] = s * q_c[i];
    a[3][i] = s * ((det_c[i] - u_c[i]) - m * q_c[i]);
    mag[0] += std::fabs(det_c[i]);
    mag[1] += std::fabs(u_c[i]);
    mag[2] += std::fabs(q_c[i]);
    mag[3] += std::fabs(det_c[i]) + std::fabs(u_c[i]) + m * std::fabs(q_c[i]);
  }
  const Thresholds<double> c = thresholds<double>(terms, in, m);
  // Upper bounds of the threshold terms' magnitudes (the c[k] are differences of such terms).
  const double m1 = m - 1;
  const double cmag[4] = {m * m * double(in.abs_t + 1) + m1 * double(terms.l1_edge1) + 3 * m1 * m,
                          m * m + m1 * double(in.l1_tvec) + 3 * m1 * m, m + 3 * m1,
                          m * m + m1 * double(terms.l1_edge1 + in.l1_tvec) + 6 * m1 * m};
  const double sx = double(start.x), sy = double(start.y), sz = double(start.z);
  for (int k = 0; k < 4; ++k) {
    ax_[k] = a[k][0];
    ay_[k] = a[k][1];
    az_[k] = a[k][2];
    // a . (end - start) >= c  <=>  a . end >= c + a . start.
    const double reference = c.c[k] + (a[k][0] * sx + a[k][1] * sy + a[k][2] * sz);
    const double scale = m * mag[k] + cmag[k];
    threshold_[k] = reference - 0x1p-44 * scale;
    // Float: rounding a to float moves it by 2^-24 |a|, and each product and sum of the box
    // test rounds by 2^-24 of at most M * sum |a|: below 6 * 2^-24 of the scale in all, with
    // the double part's error on top. 2^-20 covers both with room to spare.
    threshold_float_[k] = round_down(reference - 0x1p-20 * scale);
    for (int i = 0; i < 3; ++i) {
      const float coefficient = static_cast<float>(a[k][i]);
      const bool upper = coefficient >= 0;  // the box's upper bound on axis i maximises this term
      upper_float_[k][i] = select<float>(upper, coefficient, 0.0f);
      lower_float_[k][i] = select<float>(upper, 0.0f, coefficient);
    }
  }
}

}  // namespace rc::pipeline
