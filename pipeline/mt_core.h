// The fixed-point Moller-Trumbore pipeline, written once and templated on the integer type:
// int32_t (fast path, widths <= 15), int64_t (every width 7..31) and __int128 (an overflow
// oracle for tests). Every value is an integer count of 2^-N; the arithmetic is exactly the
// hardware's (paper sec 3.1-3.4):
//   * products are truncated back to N fractional bits by an arithmetic shift right by N, which
//     is two's-complement truncation, i.e. floor(a*b / 2^N); integer bits grow as needed;
//   * sums and differences are exact;
//   * the multiplications by sign(det) are exact (the sign is an integer +-1, no fractional bits).
// A Probe observes every one of the 27 multiplier and 18 add/sub outputs; NoProbe compiles away.
// In debug builds every operand and result is asserted against bit_bounds.h.
#pragma once

#include <cassert>

#include "pipeline/bit_bounds.h"
#include "pipeline/fixed_format.h"
#include "pipeline/hardware_blocks.h"

namespace rc::pipeline {

// Outputs of the paper's three stages (sec 3.2), named as in its figures where it names them.
template <class Int>
struct Stage1Values {
  IntVec3<Int> pvec;  // temp1 = dir x edge2
  IntVec3<Int> tvec;  // temp2 = start - v0
};

template <class Int>
struct Stage2Values {
  IntVec3<Int> qvec;  // temp3 = tvec x edge1
  Int det;            // edge1 . pvec
};

template <class Int>
struct Stage3Values {
  Int u, v, t;  // tvec . pvec, dir . qvec, edge2 . qvec (not yet divided by det: sec 3.1)
  Int sign;     // -1 if det's sign bit is set, else +1 (so det == 0 counts as positive)
  Int abs_det;  // det negated and selected by the sign bit
  Int u_signed, v_signed, t_signed;  // u*s, v*s, t*s
  Int uv_sum;                        // u*s + v*s
  bool hit;
};

template <class Int>
struct PipelineValues {
  IntVec3<Int> direction;  // end - start, formed at the pipeline's input
  Stage1Values<Int> stage1;
  Stage2Values<Int> stage2;
  Stage3Values<Int> stage3;
};

// Observes nothing; every call inlines to nothing.
struct NoProbe {
  template <class Int>
  void multiplier(Multiplier, Int) {}
  template <class Int>
  void add_sub(AddSub, Int) {}
};

namespace core {

template <class Int>
constexpr bool in_range(Quantity q, int bits, Int v) {
  const ValueRange r = value_range(q, bits);
  return Int(r.lo) <= v && v <= Int(r.hi);
}

template <class Int, class Probe>
Int multiply(Multiplier m, Int a, Int b, int bits, Probe& probe) {
  assert(in_range(operands_of(m).a, bits, a) && in_range(operands_of(m).b, bits, b));
  // Arithmetic shift of a negative value is floor (two's-complement truncation); GCC and Clang
  // define it so, and C++20 makes it standard.
  const Int product = (a * b) >> bits;
  assert(in_range(result_of(m), bits, product));
  probe.multiplier(m, product);
  return product;
}

template <class Int, class Probe>
Int multiply_by_sign(Multiplier m, Int value, Int sign, [[maybe_unused]] int bits, Probe& probe) {
  assert(in_range(Quantity::Dot, bits, value) && (sign == 1 || sign == -1));
  const Int product = value * sign;
  probe.multiplier(m, product);
  return product;
}

template <class Int, class Probe>
Int add(AddSub id, Int a, Int b, [[maybe_unused]] int bits, Probe& probe) {
  const Int sum = a + b;
  assert(in_range(result_of(id), bits, sum));
  probe.add_sub(id, sum);
  return sum;
}

template <class Int, class Probe>
Int subtract(AddSub id, Int a, Int b, [[maybe_unused]] int bits, Probe& probe) {
  const Int difference = a - b;
  assert(in_range(result_of(id), bits, difference));
  probe.add_sub(id, difference);
  return difference;
}

constexpr Multiplier next(Multiplier m, int k) { return static_cast<Multiplier>(static_cast<int>(m) + k); }
constexpr AddSub next(AddSub a, int k) { return static_cast<AddSub>(static_cast<int>(a) + k); }

// a x b on six multipliers (first, first+1, ...) and three subtractors (first_sub, ...).
template <class Int, class Probe>
IntVec3<Int> cross(const IntVec3<Int>& a, const IntVec3<Int>& b, Multiplier first,
                   AddSub first_sub, int bits, Probe& probe) {
  const auto mul = [&](int k, Int x, Int y) { return multiply(next(first, k), x, y, bits, probe); };
  const auto sub = [&](int k, Int x, Int y) { return subtract(next(first_sub, k), x, y, bits, probe); };
  return {sub(0, mul(0, a.y, b.z), mul(1, a.z, b.y)),
          sub(1, mul(2, a.z, b.x), mul(3, a.x, b.z)),
          sub(2, mul(4, a.x, b.y), mul(5, a.y, b.x))};
}

// a . b on three multipliers and two serial adders: (x + y) + z (sec 3.2).
template <class Int, class Probe>
Int dot(const IntVec3<Int>& a, const IntVec3<Int>& b, Multiplier first, AddSub partial, int bits,
        Probe& probe) {
  const Int xy = add(partial, multiply(first, a.x, b.x, bits, probe),
                     multiply(next(first, 1), a.y, b.y, bits, probe), bits, probe);
  return add(next(partial, 1), xy, multiply(next(first, 2), a.z, b.z, bits, probe), bits, probe);
}

// The division-free decision of sec 3.1, branch-free so that a batch loop vectorises:
// 0 < u*s < |det|, 0 < v*s, u*s + v*s < |det|, 0 < t*s < |det|. Every comparison is strict, so
// a crossing exactly on an edge or vertex, or an end point exactly on the plane, is a miss; and
// det == 0 can never hit because 0 < t*s < 0 is impossible.
template <class Int>
bool decide(const Stage3Values<Int>& s) {
  return (Int(0) < s.u_signed) & (s.u_signed < s.abs_det) & (Int(0) < s.v_signed) &
         (s.uv_sum < s.abs_det) & (Int(0) < s.t_signed) & (s.t_signed < s.abs_det);
}

// The same with a guard band of g LSBs on t (docs/pipeline.md, "The t guard band"): the segment
// counts as blocked only for g < t*s < |det| - g, i.e. t in (g/|det|, 1 - g/|det|) of the segment;
// u and v are tested as in decide(). g = 0 is decide() exactly. In hardware: one subtractor
// (|det| - g, formed beside |det| while the dot products run) and the comparison against 0 widened
// to one against g, both of the t width.
template <class Int>
bool decide(const Stage3Values<Int>& s, Int t_guard) {
  return (Int(0) < s.u_signed) & (s.u_signed < s.abs_det) & (Int(0) < s.v_signed) &
         (s.uv_sum < s.abs_det) & (t_guard < s.t_signed) & (s.t_signed < s.abs_det - t_guard);
}

}  // namespace core

// Stage 1: pvec = dir x edge2 and tvec = start - v0.
template <class Int, class Probe>
Stage1Values<Int> stage1(const IntVec3<Int>& v0, const IntVec3<Int>& edge2,
                         const IntVec3<Int>& start, const IntVec3<Int>& direction, int bits,
                         Probe& probe) {
  using core::subtract;
  return {core::cross(direction, edge2, Multiplier::PvecX_DirY_Edge2Z, AddSub::PvecX, bits, probe),
          {subtract(AddSub::TvecX, start.x, v0.x, bits, probe),
           subtract(AddSub::TvecY, start.y, v0.y, bits, probe),
           subtract(AddSub::TvecZ, start.z, v0.z, bits, probe)}};
}

// Stage 2: qvec = tvec x edge1 and det = edge1 . pvec.
template <class Int, class Probe>
Stage2Values<Int> stage2(const IntVec3<Int>& edge1, const Stage1Values<Int>& s1, int bits,
                         Probe& probe) {
  return {core::cross(s1.tvec, edge1, Multiplier::QvecX_TvecY_Edge1Z, AddSub::QvecX, bits, probe),
          core::dot(edge1, s1.pvec, Multiplier::DetX, AddSub::DetPartial, bits, probe)};
}

// Stage 3: u, v, t, their products with sign(det), u*s + v*s and the decision. |det| is formed
// here, in parallel with the dot products, as the paper does (sec 3.2).
template <class Int, class Probe>
Stage3Values<Int> stage3(const IntVec3<Int>& edge2, const IntVec3<Int>& direction,
                         const Stage1Values<Int>& s1, const Stage2Values<Int>& s2, int bits,
                         Probe& probe) {
  Stage3Values<Int> r;
  r.u = core::dot(s1.tvec, s1.pvec, Multiplier::UX, AddSub::UPartial, bits, probe);
  r.v = core::dot(direction, s2.qvec, Multiplier::VX, AddSub::VPartial, bits, probe);
  r.t = core::dot(edge2, s2.qvec, Multiplier::TX, AddSub::TPartial, bits, probe);
  const bool negative = s2.det < 0;  // det's most significant bit
  r.sign = negative ? Int(-1) : Int(1);
  r.abs_det = negative ? Int(-s2.det) : s2.det;
  r.u_signed = core::multiply_by_sign(Multiplier::SignU, r.u, r.sign, bits, probe);
  r.v_signed = core::multiply_by_sign(Multiplier::SignV, r.v, r.sign, bits, probe);
  r.t_signed = core::multiply_by_sign(Multiplier::SignT, r.t, r.sign, bits, probe);
  r.uv_sum = core::add(AddSub::UPlusV, r.u_signed, r.v_signed, bits, probe);
  r.hit = core::decide(r);
  return r;
}

// The whole pipeline for one face and one segment. Requires core_fits<Int>(bits).
template <class Int, class Probe>
PipelineValues<Int> run_pipeline(const IntVec3<Int>& v0, const IntVec3<Int>& edge1,
                                 const IntVec3<Int>& edge2, const IntVec3<Int>& start,
                                 const IntVec3<Int>& end, int bits, Probe& probe) {
  PipelineValues<Int> r;
  r.direction = end - start;
  r.stage1 = stage1(v0, edge2, start, r.direction, bits, probe);
  r.stage2 = stage2(edge1, r.stage1, bits, probe);
  r.stage3 = stage3(edge2, r.direction, r.stage1, r.stage2, bits, probe);
  return r;
}

template <class Int>
bool pipeline_hits(const IntVec3<Int>& v0, const IntVec3<Int>& edge1, const IntVec3<Int>& edge2,
                   const IntVec3<Int>& start, const IntVec3<Int>& end, int bits) {
  NoProbe probe;
  return run_pipeline(v0, edge1, edge2, start, end, bits, probe).stage3.hit;
}

// The same decision with a guard band of t_guard LSBs on t (decide(s, t_guard)). Always inlined: the
// streaming kernels' guarded loops vectorise only with it inlined (without, GCC 12 called it once per end
// point: 0.1 G tests/s against 2.3 G, bench_pipeline's BM_FixedKernelTGuard).
template <class Int>
[[gnu::always_inline]] inline bool pipeline_hits(const IntVec3<Int>& v0, const IntVec3<Int>& edge1, const IntVec3<Int>& edge2,
                   const IntVec3<Int>& start, const IntVec3<Int>& end, int bits, Int t_guard) {
  NoProbe probe;
  return core::decide(run_pipeline(v0, edge1, edge2, start, end, bits, probe).stage3, t_guard);
}

}  // namespace rc::pipeline
