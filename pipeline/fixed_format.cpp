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

}  // namespace rc::pipeline
