#include "pipeline/hit_region.h"

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

FaceStartValues face_start_values(const FaceRecord& face, const FixedVec3& start, FracBits bits) {
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

// Everything the four conditions are built from (docs/fast-visibility.md, "The four conditions").
// Unit: 2^-bits, so M = 2^bits is "1.0".
struct ConditionInputs {
  bool empty;
  int sign;             // s = sign(t): the sign det must have for a hit
  std::int64_t abs_t;
  FixedVec3 n_det;      // det = d . n_det / M^2 + error  (n_det = edge2 x edge1)
  FixedVec3 n_u;        // u   = d . n_u / M^2 + error    (n_u = edge2 x tvec)
  FixedVec3 qvec;       // v   = d . qvec / M + error
  std::int64_t l1_edge1, l1_tvec;
};

ConditionInputs condition_inputs(const FaceRecord& face, const FixedVec3& start, FracBits bits) {
  const FaceStartValues f = face_start_values(face, start, bits);
  ConditionInputs in{};
  in.empty = f.t == 0;
  in.sign = f.t > 0 ? 1 : -1;
  in.abs_t = std::llabs(f.t);
  in.n_det = exact_cross(face.edge2, face.edge1);
  in.n_u = exact_cross(face.edge2, f.tvec);
  in.qvec = f.qvec;
  in.l1_edge1 = l1_norm(face.edge1);
  in.l1_tvec = l1_norm(f.tvec);
  return in;
}

template <class Num>
struct Thresholds {
  Num c[4];
};

// The four thresholds c[k] of a[k] . d >= c[k], scaled so that a[k] are integer vectors:
// conditions 0, 1 and 3 are multiplied by M^2, condition 2 by M. Each subtracted term is the
// most truncation can add to the left-hand side (docs/fast-visibility.md): a dot product of three
// truncated products lies at most 3(M-1)/M below its untruncated value, and a truncated cross
// component dotted with w moves it by at most |w|_1 (M-1)/M^2 either way.
template <class Num>
Thresholds<Num> thresholds(const ConditionInputs& in, Num m) {
  const Num m1 = m - 1;
  const bool pos = in.sign > 0;
  Thresholds<Num> r;
  // s*det >= |t| + 1. det <= d.n_det/M^2 + (M-1)|e1|/M^2; -det <= -d.n_det/M^2 + same + 3(M-1)/M.
  r.c[0] = m * m * Num(in.abs_t + 1) - m1 * Num(in.l1_edge1) - (pos ? Num(0) : 3 * m1 * m);
  // s*u >= 1, the same shape with tvec in place of edge1.
  r.c[1] = m * m - m1 * Num(in.l1_tvec) - (pos ? Num(0) : 3 * m1 * m);
  // s*v >= 1. v <= d.qvec/M; -v <= -d.qvec/M + 3(M-1)/M.
  r.c[2] = m - (pos ? Num(0) : 3 * m1);
  // s*(det - u - v) >= 1: the errors of det, u and v add up.
  r.c[3] = m * m - m1 * Num(in.l1_edge1 + in.l1_tvec) - (pos ? 6 : 3) * m1 * m;
  return r;
}

}  // namespace

ExactHitConditions exact_hit_conditions(const FaceRecord& face, const FixedVec3& start, FracBits bits) {
  const ConditionInputs in = condition_inputs(face, start, bits);
  ExactHitConditions r;
  r.empty = in.empty;
  const __int128 m = __int128{1} << bits, s = in.sign;
  const auto wide = [](std::int64_t v) { return static_cast<__int128>(v); };
  const std::int64_t det_c[3] = {in.n_det.x, in.n_det.y, in.n_det.z};
  const std::int64_t u_c[3] = {in.n_u.x, in.n_u.y, in.n_u.z};
  const std::int64_t q_c[3] = {in.qvec.x, in.qvec.y, in.qvec.z};
  for (int i = 0; i < 3; ++i) {
    r.a[0][i] = s * wide(det_c[i]);
    r.a[1][i] = s * wide(u_c[i]);
    r.a[2][i] = s * wide(q_c[i]);
    r.a[3][i] = s * (wide(det_c[i]) - wide(u_c[i]) - m * wide(q_c[i]));
  }
  const Thresholds<__int128> c = thresholds<__int128>(in, m);
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
  return static_cast<double>(f) <= x ? f : static_cast<float>(x - std::fabs(x) * 0x1p-23);
}

}  // namespace

// The double version. Every quantity below is an integer of at most about 2^98; converting and
// combining them in double rounds each step by a relative 2^-53. The sum of all those roundings,
// in computing a[k], c[k], the threshold and later the reach of a box, is below
// 20 * 2^-53 * G[k], where G[k] = M * sum_i mag[k][i] + cmag[k] bounds every term involved
// (coordinates are below M). Lowering the threshold by 2^-44 * G[k], far more than that, keeps
// the double test conservative; at 31 bits it costs under 1/1000 of an LSB of tightness.
HitRegion::HitRegion(const FaceRecord& face, const FixedVec3& start, FracBits bits) {
  const ConditionInputs in = condition_inputs(face, start, bits);
  if (in.empty) {
    empty_ = true;
    for (double& t : threshold_) t = std::numeric_limits<double>::infinity();
    for (float& t : threshold_float_) t = std::numeric_limits<float>::infinity();
    return;
  }
  const double m = static_cast<double>(std::int64_t{1} << bits), s = in.sign;
  const double det_c[3] = {double(in.n_det.x), double(in.n_det.y), double(in.n_det.z)};
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
  const Thresholds<double> c = thresholds<double>(in, m);
  // Upper bounds of the threshold terms' magnitudes (the c[k] are differences of such terms).
  const double m1 = m - 1;
  const double cmag[4] = {m * m * double(in.abs_t + 1) + m1 * double(in.l1_edge1) + 3 * m1 * m,
                          m * m + m1 * double(in.l1_tvec) + 3 * m1 * m, m + 3 * m1,
                          m * m + m1 * double(in.l1_edge1 + in.l1_tvec) + 6 * m1 * m};
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
      a_float_[k][i] = coefficient;
      const int upper = coefficient >= 0 ? 1 : 0;  // bound[upper][i] maximises this term
      offset_[k][i] = (upper * 3 + i) * kBoxes;
    }
  }
}

}  // namespace rc::pipeline
