// Value ranges of every intermediate of the fixed-point pipeline, derived by interval arithmetic
// from the input ranges. This is the overflow proof of docs/pipeline.md in executable form: the
// core asserts every value against these ranges in debug builds, the tests check that extreme
// inputs stay inside them, and the resource model sizes multiplier operands from them.
#pragma once

#include <cstdint>

#include "pipeline/fixed_format.h"

namespace rc::pipeline {

// The kinds of value that flow through the pipeline, in dataflow order.
enum class Quantity {
  Position,        // 0.N input: start, end, v0
  Difference,      // 1.N: direction, edge1, edge2, tvec
  Product1Raw,     // Difference x Difference before truncation (pvec and qvec multipliers)
  Product1,        // ... after dropping N fractional bits
  CrossComponent,  // Product1 - Product1: pvec, qvec
  Product2Raw,     // Difference x CrossComponent before truncation (det, u, v, t multipliers)
  Product2,        // ... after truncation
  DotPartial,      // Product2 + Product2
  Dot,             // DotPartial + Product2: det, u, v, t
  Sign,            // sign(det) as the integer +-1 fed to the last three multipliers
  SignedDot,       // Dot x Sign: u*s, v*s, t*s (an exact product: Sign has no fractional bits)
  AbsDet,          // |det|, the negate-and-select of sec 3.1
  UvSum,           // u*s + v*s
};
constexpr int kQuantityCount = 13;

// Inclusive range of integer values (units of 2^-N).
struct ValueRange {
  std::int64_t lo, hi;
  constexpr bool contains(std::int64_t v) const { return lo <= v && v <= hi; }
};

namespace bounds_detail {

using Wide = __int128;
struct Interval {
  Wide lo, hi;
};

constexpr Wide min4(Wide a, Wide b, Wide c, Wide d) {
  Wide m = a < b ? a : b;
  m = m < c ? m : c;
  return m < d ? m : d;
}
constexpr Wide max4(Wide a, Wide b, Wide c, Wide d) {
  Wide m = a > b ? a : b;
  m = m > c ? m : c;
  return m > d ? m : d;
}
constexpr Interval mul(Interval a, Interval b) {
  return {min4(a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi),
          max4(a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi)};
}
constexpr Interval add(Interval a, Interval b) { return {a.lo + b.lo, a.hi + b.hi}; }
constexpr Interval sub(Interval a, Interval b) { return {a.lo - b.hi, a.hi - b.lo}; }
// Truncation by an arithmetic shift is floor division, which is monotone: bounds map to bounds.
constexpr Interval shr(Interval a, int bits) { return {a.lo >> bits, a.hi >> bits}; }
constexpr Wide max_abs(Interval a) { return -a.lo > a.hi ? -a.lo : a.hi; }

constexpr Interval interval(Quantity q, int bits) {
  const Interval position{0, (Wide{1} << bits) - 1};
  const Interval difference = sub(position, position);
  const Interval product1_raw = mul(difference, difference);
  const Interval product1 = shr(product1_raw, bits);
  const Interval cross = sub(product1, product1);
  const Interval product2_raw = mul(difference, cross);
  const Interval product2 = shr(product2_raw, bits);
  const Interval dot_partial = add(product2, product2);
  const Interval dot = add(dot_partial, product2);
  const Interval sign{-1, 1};
  const Interval signed_dot = mul(dot, sign);
  const Interval abs_det{0, max_abs(dot)};
  const Interval uv_sum = add(signed_dot, signed_dot);
  switch (q) {
    case Quantity::Position: return position;
    case Quantity::Difference: return difference;
    case Quantity::Product1Raw: return product1_raw;
    case Quantity::Product1: return product1;
    case Quantity::CrossComponent: return cross;
    case Quantity::Product2Raw: return product2_raw;
    case Quantity::Product2: return product2;
    case Quantity::DotPartial: return dot_partial;
    case Quantity::Dot: return dot;
    case Quantity::Sign: return sign;
    case Quantity::SignedDot: return signed_dot;
    case Quantity::AbsDet: return abs_det;
    case Quantity::UvSum: return uv_sum;
  }
  return {0, 0};
}

}  // namespace bounds_detail

namespace bounds_detail {

constexpr ValueRange to_range(Interval i) {
  return {static_cast<std::int64_t>(i.lo), static_cast<std::int64_t>(i.hi)};
}

// Every range at every supported width, computed at compile time (the debug asserts look
// ranges up on every operation).
struct RangeTable {
  ValueRange ranges[kMaxFracBits - kMinFracBits + 1][kQuantityCount];
};
constexpr RangeTable make_range_table() {
  RangeTable table{};
  for (int bits = kMinFracBits; bits <= kMaxFracBits; ++bits) {
    for (int q = 0; q < kQuantityCount; ++q) {
      table.ranges[bits - kMinFracBits][q] = to_range(interval(static_cast<Quantity>(q), bits));
    }
  }
  return table;
}
inline constexpr RangeTable kRangeTable = make_range_table();

}  // namespace bounds_detail

// The range a quantity can take at `bits` fractional bits, for any inputs in range.
constexpr ValueRange value_range(Quantity q, int bits) {
  if (is_valid_frac_bits(bits)) {
    return bounds_detail::kRangeTable.ranges[bits - kMinFracBits][static_cast<int>(q)];
  }
  return bounds_detail::to_range(bounds_detail::interval(q, bits));
}

// Two's-complement width (sign included) that holds every value of the quantity: the register
// width the hardware needs.
constexpr int signed_bits(Quantity q, int bits) {
  const bounds_detail::Interval i = bounds_detail::interval(q, bits);
  int w = 1;
  while (i.lo < -(bounds_detail::Wide{1} << (w - 1)) || i.hi > (bounds_detail::Wide{1} << (w - 1)) - 1) ++w;
  return w;
}

// The widest value the arithmetic ever holds is a raw second-level product (2N+2 bits); a core
// instantiated on Int is safe for `bits` iff that product fits.
template <class Int>
constexpr bool core_fits(int bits) {
  return signed_bits(Quantity::Product2Raw, bits) <= static_cast<int>(sizeof(Int) * 8);
}

static_assert(signed_bits(Quantity::Product2Raw, kMaxFracBits) == 64,
              "at 31 bits the widest product needs exactly 64 bits");
static_assert(core_fits<std::int64_t>(kMaxFracBits), "the 64-bit core covers every width");
static_assert(core_fits<std::int32_t>(15) && !core_fits<std::int32_t>(16),
              "the 32-bit core covers widths up to 15");
static_assert(signed_bits(Quantity::Dot, 15) == 19, "det/u/v/t are N+4 bits (Table 1's 30 mults)");

}  // namespace rc::pipeline
