#include "pipeline/fixed_format.h"

#include <stdexcept>
#include <string>

namespace rc::pipeline {

void validate_frac_bits(int bits) {
  if (!is_valid_frac_bits(bits)) {
    throw std::invalid_argument("fractional width " + std::to_string(bits) +
                                " is out of range: the pipeline supports " +
                                std::to_string(kMinFracBits) + " to " +
                                std::to_string(kMaxFracBits) + " fractional bits");
  }
}

void validate_t_guard(int t_guard) {
  if (!is_valid_t_guard(t_guard)) {
    throw std::invalid_argument("t guard " + std::to_string(t_guard) + " LSB is out of range: the pipeline takes 0 to " +
                                std::to_string(kMaxTGuard) + " LSBs (8 bits)");
  }
}

}  // namespace rc::pipeline
