#include "pipeline/arithmetic.h"

#include <stdexcept>

namespace rc::pipeline {

Arithmetic Arithmetic::parse(const std::string& text) {
  if (text == "fixed") return Arithmetic();
  Arithmetic a(parse_float_format(text));  // refuses anything that is not float:E,M in range
  a.name_ = text;
  return a;
}

const FloatFormat& Arithmetic::float_format() const {
  if (!format_) throw std::logic_error("Arithmetic::float_format: the arithmetic is fixed point");
  return *format_;
}

}  // namespace rc::pipeline
