// The pipeline's arithmetic as one typed choice: fixed point (its fractional width is a separate
// count, --bits) or a floating-point format float:E,M (pipeline/float_format.h). The text is parsed
// once, where it enters (a command's --arith, a study's formats); the code then asks is_float() and
// float_format(), never the string. Its name is the text it was parsed from ("fixed", "float:8,23"),
// as reports write it.
#pragma once

#include <optional>
#include <string>

#include "pipeline/float_format.h"

namespace rc::pipeline {

class Arithmetic {
 public:
  Arithmetic() = default;  // fixed point
  explicit Arithmetic(FloatFormat format) : format_(format), name_(format.to_string()) {}

  // "fixed", or a float format exactly as parse_float_format takes it; anything else throws
  // std::invalid_argument (the float parser's message: the text and the expected form or range).
  static Arithmetic parse(const std::string& text);

  bool is_float() const { return format_.has_value(); }
  // The float format; std::logic_error for fixed point (ask is_float() first).
  const FloatFormat& float_format() const;
  const std::string& name() const { return name_; }

  friend bool operator==(const Arithmetic& a, const Arithmetic& b) { return a.format_ == b.format_; }
  friend bool operator!=(const Arithmetic& a, const Arithmetic& b) { return !(a == b); }

 private:
  std::optional<FloatFormat> format_;
  std::string name_ = "fixed";
};

}  // namespace rc::pipeline
