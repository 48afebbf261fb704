#include "pipeline/float_format.h"

#include <cmath>
#include <stdexcept>

namespace rc::pipeline {

namespace {

void check_width(const char* what, int bits, int lo, int hi, const char* why) {
  if (bits < lo || bits > hi) {
    throw std::invalid_argument(std::string(what) + " " + std::to_string(bits) +
                                " is out of range: floating-point formats support " +
                                std::to_string(lo) + " to " + std::to_string(hi) + " " + what +
                                " (" + why + ")");
  }
}

std::uint64_t bits_of(double x) {
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

// A run of 1 to 3 decimal digits (more cannot be a supported width, and stoi cannot overflow).
bool parse_width(const std::string& text, std::size_t begin, std::size_t end, int& out) {
  if (end <= begin || end - begin > 3) return false;
  out = 0;
  for (std::size_t i = begin; i < end; ++i) {
    if (text[i] < '0' || text[i] > '9') return false;
    out = out * 10 + (text[i] - '0');
  }
  return true;
}

constexpr const char* kPrefix = "float:";

}  // namespace

FloatFormat::FloatFormat(int exponent_bits, int fraction_bits) : e_(exponent_bits), m_(fraction_bits) {
  check_width("exponent bits", e_, kMinExponentBits, kMaxExponentBits,
              "at least one normal exponent; products of two values must be normal doubles");
  check_width("fraction bits", m_, kMinFractionBits, kMaxFractionBits,
              "double rounding through double is innocuous only for precision M+1 <= 25");
  min_normal_bits_ = bits_of(min_normal());
  max_finite_bits_ = bits_of(max_finite());
}

double FloatFormat::min_normal() const { return std::ldexp(1.0, min_exponent()); }

double FloatFormat::max_finite() const {
  return std::ldexp(2.0 - std::ldexp(1.0, -m_), max_exponent());
}

std::string FloatFormat::to_string() const {
  return kPrefix + std::to_string(e_) + "," + std::to_string(m_);
}

FloatFormat parse_float_format(const std::string& text) {
  const std::string prefix = kPrefix;
  const std::size_t comma = text.find(',');
  int e = 0, m = 0;
  if (!names_float_format(text) || comma == std::string::npos ||
      !parse_width(text, prefix.size(), comma, e) || !parse_width(text, comma + 1, text.size(), m)) {
    throw std::invalid_argument("bad floating-point format '" + text +
                                "': expected float:E,M (exponent and fraction bits), e.g. "
                                "float:8,23 (single), float:5,10 (half), float:6,9");
  }
  return FloatFormat(e, m);
}

bool names_float_format(const std::string& text) { return text.rfind(kPrefix, 0) == 0; }

bool is_in_format(double x, FloatFormat f) {
  return std::isnan(x) || round_to_format(x, f) == x;
}

}  // namespace rc::pipeline
