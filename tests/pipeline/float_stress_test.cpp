// The stress suite (pipeline/stress_cases.h) on the floating-point pipeline: the properties of
// tests/pipeline/stress_properties_test.cpp that carry over to floating point, with the
// floating-point error bound in place of the fixed-point one (docs/pipeline.md, "Floating-point
// pipeline"). Which fixed-point properties do not carry over, and why, is documented there.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include "pipeline/exact_mt.h"
#include "pipeline/fixed_mt.h"
#include "pipeline/float_mt.h"
#include "pipeline/stress_cases.h"

namespace rc::pipeline {
namespace {

constexpr std::size_t kCasesPerKind = 1000;
const FloatFormat kFormats[] = {FloatFormat(8, 23), FloatFormat(5, 10), FloatFormat(6, 9)};
constexpr int kWidths[] = {7, 15, 23};  // the lattice of the [lattice] kinds

template <class F>
void for_every_case(F f) {
  for (const FloatFormat& format : kFormats) {
    for (int bits : kWidths) {
      for (int k = 0; k < kCaseKindCount; ++k) {
        const auto kind = static_cast<CaseKind>(k);
        const auto cases = make_stress_cases(kind, bits, kCasesPerKind, 42);
        for (std::size_t i = 0; i < cases.size(); ++i) {
          f(cases[i], format, std::string(name(kind)) + " case " + std::to_string(i) + " (" +
                                  std::to_string(bits) + "-bit lattice) in " + format.to_string());
        }
      }
    }
  }
}

// gamma_n = n u / (1 - n u) (Higham, Accuracy and Stability of Numerical Algorithms, sec 3.1).
double gamma(int n, double unit) { return n * unit / (1 - n * unit); }

FloatVec3 abs3(const FloatVec3& a) { return {std::fabs(a.x), std::fabs(a.y), std::fabs(a.z)}; }
FloatVec3 cross3(const FloatVec3& a, const FloatVec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
// |a| x |b| with the products added: the magnitude a cross product's rounding error scales with.
FloatVec3 cross_magnitude(const FloatVec3& a, const FloatVec3& b) {
  const FloatVec3 p = abs3(a), q = abs3(b);
  return {p.y * q.z + p.z * q.y, p.z * q.x + p.x * q.z, p.x * q.y + p.y * q.x};
}
double dot3(const FloatVec3& a, const FloatVec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

// det, u, v, t in double on the pipeline's own inputs (its rounded face record, end points and
// direction), and a proven bound on |pipeline - double| for each.
//
// Bound (standard model with flush to zero: fl(x) = x(1 + d) + e, |d| <= u = 2^-p, |e| <= eta =
// smallest normal, one of the two zero): every one of det, u, v, t is a dot product of two vectors
// at most 6 roundings deep (tvec 1, cross product 2, multiplier 1, two adders 2), so its relative
// part is at most gamma_6(u) * S, S the dot product of magnitudes with the crosses' magnitudes;
// the flushes add at most 21 eta with every difference <= 1 and cross component <= 2 in magnitude
// (inputs in [0, 1]: each cross component <= 5.1 eta, each of 3 terms <= 6.1 eta, 2 adders).
// Taken with gamma_7 and 32 eta for slack; double's own error is gamma_8(2^-53) * S.
struct Reference {
  double det, u, v, t;
  double err_det, err_u, err_v, err_t;
  double slack;  // double's rounding of the margins themselves
};

Reference reference(const FloatFaceRecord& f, const FloatVec3& start, const FloatVec3& dir,
                    FloatFormat format) {
  const FloatVec3 tvec = start - f.v0;
  const FloatVec3 pvec = cross3(dir, f.edge2), qvec = cross3(tvec, f.edge1);
  const FloatVec3 pmag = cross_magnitude(dir, f.edge2), qmag = cross_magnitude(tvec, f.edge1);
  const double relative = gamma(7, std::ldexp(1.0, -format.precision())) + gamma(8, 0x1p-53);
  const double absolute = 32 * format.min_normal();
  const double s_det = dot3(abs3(f.edge1), pmag), s_u = dot3(abs3(tvec), pmag),
               s_v = dot3(abs3(dir), qmag), s_t = dot3(abs3(f.edge2), qmag);
  const auto err = [&](double magnitude) { return relative * magnitude + absolute; };
  Reference r{dot3(f.edge1, pvec), dot3(tvec, pvec), dot3(dir, qvec), dot3(f.edge2, qvec),
              err(s_det), err(s_u), err(s_v), err(s_t), 0x1p-50 * (s_det + s_u + s_v + s_t)};
  return r;
}

// True if some compared quantity is within the bound of its threshold, so that the pipeline may
// legitimately decide otherwise than exact arithmetic (the analogue of near_decision_boundary).
bool near_boundary(const Reference& r, FloatFormat format) {
  const double s = r.det < 0 ? -1 : 1, abs_det = std::fabs(r.det), e = r.slack;
  const double uv_err = r.err_u + r.err_v +
                        std::ldexp(std::fabs(r.u) + std::fabs(r.v) + r.err_u + r.err_v, -format.precision()) +
                        format.min_normal();
  return abs_det <= r.err_det + e || std::fabs(r.u) <= r.err_u + e || std::fabs(r.v) <= r.err_v + e ||
         std::fabs(r.t) <= r.err_t + e || std::fabs(abs_det - s * r.u) <= r.err_det + r.err_u + e ||
         std::fabs(abs_det - s * r.t) <= r.err_det + r.err_t + e ||
         std::fabs(abs_det - s * (r.u + r.v)) <= r.err_det + uv_err + e;
}

bool decide(const Reference& r) {
  Stage3Values<double> s;
  s.sign = r.det < 0 ? -1 : 1;
  s.abs_det = std::fabs(r.det);
  s.u_signed = s.sign * r.u;
  s.v_signed = s.sign * r.v;
  s.t_signed = s.sign * r.t;
  s.uv_sum = s.u_signed + s.v_signed;
  return core::decide(s);
}

struct Evaluated {
  FloatTrace trace;
  Reference ref;
};

Evaluated evaluate(const StressCase& c, FloatFormat format) {
  const FloatFaceRecord face = make_float_face_record(c.triangle, format);
  const FloatVec3 s = round_point(c.start, format), e = round_point(c.end, format);
  Evaluated r{trace(face, s, e, format), {}};
  r.ref = reference(face, s, r.trace.values.direction, format);
  return r;
}

// The floating-point analogue of the truncation bound: det, u, v, t within the proven rounding
// error of the same dot products in double on the same inputs.
TEST(FloatStress, RoundingErrorOfEveryDotProductIsWithinTheBound) {
  for_every_case([](const StressCase& c, FloatFormat format, const std::string& what) {
    const Evaluated ev = evaluate(c, format);
    const PipelineValues<double>& v = ev.trace.values;
    const Reference& r = ev.ref;
    ASSERT_LE(std::fabs(v.stage2.det - r.det), r.err_det) << what;
    ASSERT_LE(std::fabs(v.stage3.u - r.u), r.err_u) << what;
    ASSERT_LE(std::fabs(v.stage3.v - r.v), r.err_v) << what;
    ASSERT_LE(std::fabs(v.stage3.t - r.t), r.err_t) << what;
  });
}

// The central accuracy claim: outside the proven band the pipeline decides as exact arithmetic
// (here double, whose own error is inside the band) on the same inputs.
TEST(FloatStress, AgreesWithDoubleOutsideTheProvenRoundingBand) {
  std::map<std::string, std::size_t> outside_band, disagreements;
  for_every_case([&](const StressCase& c, FloatFormat format, const std::string& what) {
    const Evaluated ev = evaluate(c, format);
    disagreements[format.to_string()] += ev.trace.hit() != decide(ev.ref);
    if (!near_boundary(ev.ref, format)) {
      ++outside_band[format.to_string()];
      ASSERT_EQ(ev.trace.hit(), decide(ev.ref)) << what;
    }
  });
  for (const FloatFormat& format : kFormats) {
    const std::string f = format.to_string();
    std::printf("%s: %zu of %zu cases outside the band, %zu disagree with double\n", f.c_str(),
                outside_band[f], 3 * kCaseKindCount * kCasesPerKind, disagreements[f]);
    EXPECT_GT(outside_band[f], 3000u) << f;  // exercised, not vacuous (measured 3412 to 9179)
  }
}

TEST(FloatStress, ZeroDeterminantNeverHits) {
  std::size_t zero = 0;
  for_every_case([&](const StressCase& c, FloatFormat format, const std::string& what) {
    const FloatTrace t = evaluate(c, format).trace;
    if (t.values.stage2.det == 0) {
      ++zero;
      ASSERT_FALSE(t.hit()) << what;
    }
  });
  EXPECT_GT(zero, 1000u);
}

// A zero edge is exactly zero in floating point too (x - x = 0), so every det product has a zero
// factor (edge1 = 0) or pvec = dir x 0 = 0 (edge2 = 0): det = 0, no hit.
TEST(FloatStress, FacesWithCoincidentVerticesNeverHit) {
  for (const FloatFormat& format : kFormats) {
    for (const StressCase& c : make_stress_cases(CaseKind::Crossing, 15, 500, 5)) {
      for (const Triangle& t : {Triangle{c.triangle.v0, c.triangle.v0, c.triangle.v2},
                                Triangle{c.triangle.v0, c.triangle.v1, c.triangle.v0}}) {
        const FloatTrace tr = trace(make_float_face_record(t, format), round_point(c.start, format),
                                    round_point(c.end, format), format);
        ASSERT_EQ(tr.values.stage2.det, 0);
        ASSERT_FALSE(tr.hit());
      }
    }
  }
}

// On the 7-bit lattice every intermediate is exact in a 24-bit significand (det, u, v, t are
// multiples of 2^-21 below 6 in magnitude: 24 bits) with exponents down to -21 (E >= 6): the
// float pipeline then IS the exact reference, value for value, and misses every exact boundary
// case exactly as the exact test does.
TEST(FloatStress, TwentyFourBitSignificandsAreExactOnTheSevenBitLattice) {
  constexpr int kBits = 7;
  for (const FloatFormat& format : {FloatFormat(8, 23), FloatFormat(6, 23)}) {
    for (int k = 0; k < kCaseKindCount; ++k) {
      for (const StressCase& c : make_stress_cases(static_cast<CaseKind>(k), kBits, kCasesPerKind, 3)) {
        const FaceRecord q = make_face_record(c.triangle, kBits);
        const FixedVec3 qs = quantize_point(c.start, kBits), qe = quantize_point(c.end, kBits);
        const auto point = [](const FixedVec3& p) {
          return Vec3{std::ldexp(double(p.x), -kBits), std::ldexp(double(p.y), -kBits), std::ldexp(double(p.z), -kBits)};
        };
        const Triangle lattice{point(q.v0), point(q.v0 + q.edge1), point(q.v0 + q.edge2)};
        const FloatTrace t = trace(make_float_face_record(lattice, format), round_point(point(qs), format),
                                   round_point(point(qe), format), format);
        const ExactValues e = exact_values(q, qs, qe);
        const auto exact = [](__int128 x) { return std::ldexp(static_cast<double>(x), -3 * kBits); };
        ASSERT_EQ(t.values.stage2.det, exact(e.det)) << name(static_cast<CaseKind>(k));
        ASSERT_EQ(t.values.stage3.u, exact(e.u));
        ASSERT_EQ(t.values.stage3.v, exact(e.v));
        ASSERT_EQ(t.values.stage3.t, exact(e.t));
        ASSERT_EQ(t.hit(), e.hit) << name(static_cast<CaseKind>(k)) << " in " << format.to_string();
      }
    }
  }
}

}  // namespace
}  // namespace rc::pipeline
