// The pipeline's number format: N fractional bits (7..31), positions unsigned 0.N, differences
// signed 1.N, every quantity held as an integer count of 2^-N (paper sec 3.3).
#pragma once

#include <cstdint>

namespace rc::pipeline {

// The paper synthesised 7, 15, 23 and 31 fractional bits (sec 5.2); the model accepts every width
// in between. 31 is also the widest whose products fit a 64-bit integer (see bit_bounds.h).
constexpr int kMinFracBits = 7;
constexpr int kMaxFracBits = 31;

constexpr bool is_valid_frac_bits(int bits) { return bits >= kMinFracBits && bits <= kMaxFracBits; }

// Throws std::invalid_argument naming the width and the accepted range.
void validate_frac_bits(int bits);

// The guard band on the pipeline's t test, in LSBs of t*s (mt_core.h, core::decide(s, t_guard)): a
// segment is blocked only for g < t*s < |det| - g. 0 is the paper's test. The wrapper's T_GUARD
// register holds it in 8 bits (board/register_map.h), the RTL's t_guard input too, so 0..255.
constexpr int kMaxTGuard = 255;
constexpr bool is_valid_t_guard(int t_guard) { return t_guard >= 0 && t_guard <= kMaxTGuard; }
// Throws std::invalid_argument naming the guard and the accepted range.
void validate_t_guard(int t_guard);

// A fractional width the pipeline supports, valid by construction: the width is checked once, when
// an int becomes a FracBits (std::invalid_argument naming it and the range), and every function that
// takes a FracBits relies on it instead of checking again. The conversion from int is implicit on
// purpose, so each call site with a bare width is checked at the call; the value reads as an int.
class FracBits {
 public:
  FracBits(int bits) : bits_(bits) {  // NOLINT(google-explicit-constructor): checked conversion
    validate_frac_bits(bits);
  }
  constexpr operator int() const { return bits_; }  // NOLINT(google-explicit-constructor)
  constexpr int value() const { return bits_; }

 private:
  int bits_;
};

// A 3-vector of fixed-point integers. The generic core is templated on the integer type (32-bit,
// 64-bit or 128-bit); the public API speaks FixedVec3 = IntVec3<int64_t>.
template <class Int>
struct IntVec3 {
  Int x, y, z;
};

template <class Int>
constexpr bool operator==(const IntVec3<Int>& a, const IntVec3<Int>& b) {
  return a.x == b.x && a.y == b.y && a.z == b.z;
}
template <class Int>
constexpr bool operator!=(const IntVec3<Int>& a, const IntVec3<Int>& b) {
  return !(a == b);
}
template <class Int>
constexpr IntVec3<Int> operator+(const IntVec3<Int>& a, const IntVec3<Int>& b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
template <class Int>
constexpr IntVec3<Int> operator-(const IntVec3<Int>& a, const IntVec3<Int>& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}

// Widens or narrows the component type. Narrowing is only used where bit_bounds.h proves the
// values fit.
template <class To, class From>
constexpr IntVec3<To> vec_cast(const IntVec3<From>& v) {
  return {static_cast<To>(v.x), static_cast<To>(v.y), static_cast<To>(v.z)};
}

using FixedVec3 = IntVec3<std::int64_t>;

// One face as the hardware's face bank holds it: 9 words (paper sec 4.4), vertex 0 as a 0.N
// position and the two edges as exact 1.N differences of quantised vertices.
struct FaceRecord {
  FixedVec3 v0, edge1, edge2;
};

inline bool operator==(const FaceRecord& a, const FaceRecord& b) {
  return a.v0 == b.v0 && a.edge1 == b.edge1 && a.edge2 == b.edge2;
}

}  // namespace rc::pipeline
