// A binary floating-point format for the floating-point version of the pipeline (paper sec 6,
// future work; docs/pipeline.md, "Floating-point pipeline"): E exponent bits, M fraction bits,
// IEEE 754 layout (sign, biased exponent, hidden leading 1), value = (-1)^s * 1.f * 2^(e - bias),
// bias = 2^(E-1) - 1, exponent field all ones reserved for infinity and NaN, exponent field all
// zeros for zero only: no subnormals.
//
// Rounding, as a vendor core does it (the Xilinx LogiCORE Floating-Point Operator, DS335 / PG060,
// is the model: round to nearest even only, no denormalised numbers, overflow to infinity):
//   * round to nearest, ties to even, to p = M + 1 significant bits, as if the exponent range
//     were unbounded;
//   * then, if the rounded magnitude is below the smallest normal 2^(1 - bias): +-0 (flush to
//     zero, sign kept; tininess is detected AFTER rounding, so a value that rounds up to the
//     smallest normal is that normal);
//   * if the rounded magnitude is above the largest finite (2 - 2^-M) * 2^bias: +-infinity;
//   * infinity and NaN follow IEEE 754 (inf - inf, 0 * inf -> NaN; every comparison with NaN is
//     false). Subnormal operands cannot occur: every value is the output of this rounding.
//
// Supported range: 2 <= E <= 10 and 1 <= M <= 24. Why, for the evaluation trick used here (each
// operation computed in double, then rounded once to the format):
//   * a product of two p-bit significands has at most 2p <= 50 bits, and with E <= 10 every
//     product of two format values lies in [2^-1020, 2^1024), a normal double: the product is
//     EXACT in double, so rounding it once is correct rounding;
//   * a sum or difference is rounded twice (to double, then to the format); Figueroa (1995, "When
//     is double rounding innocuous?") proves that harmless for + - x when the wider precision
//     53 >= 2p + 2, i.e. p <= 25, M <= 24. The exact sum of two format values is never
//     in double's subnormal range (E <= 10), and when its magnitude is below the format's smallest
//     normal it is exact in double, so flush and overflow see the correctly rounded value too;
//   * E >= 2 is the least that leaves a normal exponent beside the reserved all-zeros and
//     all-ones fields (E = 2: exponents 0 and 1 only).
// That covers half (5,10), bfloat16 (8,7), single (8,23) and every narrower custom format, with
// double (11,52) itself out of range.
#pragma once

#include <cstdint>
#include <cstring>
#include <string>

namespace rc::pipeline {

constexpr int kMinExponentBits = 2;
constexpr int kMaxExponentBits = 10;
constexpr int kMinFractionBits = 1;
constexpr int kMaxFractionBits = 24;

// A supported (E, M) pair, valid by construction: the one constructor checks both widths and
// throws std::invalid_argument naming the offending width and its limits.
class FloatFormat {
 public:
  FloatFormat(int exponent_bits, int fraction_bits);

  int exponent_bits() const { return e_; }
  int fraction_bits() const { return m_; }
  int precision() const { return m_ + 1; }             // significant bits, hidden bit included
  int bits_per_value() const { return 1 + e_ + m_; }   // sign + exponent + fraction
  int bias() const { return (1 << (e_ - 1)) - 1; }
  int min_exponent() const { return 1 - bias(); }      // of the smallest normal
  int max_exponent() const { return bias(); }          // of the largest finite
  double min_normal() const;                           // 2^min_exponent
  double max_finite() const;                           // (2 - 2^-M) * 2^max_exponent
  std::string to_string() const;                       // "float:E,M"

  // Bit patterns (as doubles) of the smallest normal and largest finite magnitude: what
  // round_to_format compares against.
  std::uint64_t min_normal_bits() const { return min_normal_bits_; }
  std::uint64_t max_finite_bits() const { return max_finite_bits_; }

  friend bool operator==(const FloatFormat& a, const FloatFormat& b) { return a.e_ == b.e_ && a.m_ == b.m_; }
  friend bool operator!=(const FloatFormat& a, const FloatFormat& b) { return !(a == b); }

 private:
  int e_, m_;
  std::uint64_t min_normal_bits_, max_finite_bits_;
};

// "float:E,M" (as `--arith float:8,23` spells it), exactly: the prefix, two decimal numbers and
// one comma, nothing else. Throws std::invalid_argument quoting the text and the expected form,
// or the constructor's range error.
FloatFormat parse_float_format(const std::string& text);

// True if `text` asks for a floating-point format ("float:..."), whether or not it parses; plain
// "float" (the double-precision software backend) is not one.
bool names_float_format(const std::string& text);

// x rounded to the format by the rules above: one correct rounding of the double x (so converting
// an input coordinate is RNE from double). NaN and infinities pass through.
inline double round_to_format(double x, FloatFormat f) {
  constexpr std::uint64_t kSign = std::uint64_t{1} << 63;
  constexpr std::uint64_t kInfinity = 0x7ff0000000000000u;
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  const std::uint64_t sign = bits & kSign;
  std::uint64_t magnitude = bits ^ sign;
  if (magnitude >= kInfinity) return x;
  // Round to nearest even at fraction bit M: add just under half an ulp, plus one if the kept
  // last bit is odd, then clear the dropped bits. A carry out of the fraction moves into the
  // exponent field, which is exactly the renormalisation. (Double subnormals round on their own
  // grid here, but they are far below every format's smallest normal and flush below.)
  const int dropped = 52 - f.fraction_bits();
  magnitude += ((std::uint64_t{1} << (dropped - 1)) - 1) + ((magnitude >> dropped) & 1);
  magnitude &= ~((std::uint64_t{1} << dropped) - 1);
  if (magnitude < f.min_normal_bits()) magnitude = 0;            // flush to zero, after rounding
  else if (magnitude > f.max_finite_bits()) magnitude = kInfinity;  // overflow to infinity
  bits = sign | magnitude;
  double r;
  std::memcpy(&r, &bits, sizeof r);
  return r;
}

// True if x is a value of the format (rounding leaves it unchanged); NaN counts as one.
bool is_in_format(double x, FloatFormat f);

}  // namespace rc::pipeline
