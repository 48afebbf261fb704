// How many pipeline lanes (pipeline instances) a design has, valid by construction: at least one,
// and at most 255, what the wrapper's CONFIG register can hold (register_map.h). The count is
// checked once, when a number becomes a LaneCount (std::invalid_argument naming it and the range);
// everything that takes a LaneCount relies on it. The conversion from any integer is implicit on
// purpose, so each call site with a bare count is checked at the call; the value reads as unsigned.
#pragma once

#include <stdexcept>
#include <string>
#include <type_traits>

namespace rc::board {

class LaneCount {
 public:
  static constexpr unsigned kMax = 255;

  template <class Int, std::enable_if_t<std::is_integral_v<Int>, int> = 0>
  LaneCount(Int lanes) : lanes_(checked(lanes)) {}  // NOLINT(google-explicit-constructor): checked conversion
  constexpr operator unsigned() const { return lanes_; }  // NOLINT(google-explicit-constructor)
  constexpr unsigned value() const { return lanes_; }

 private:
  template <class Int>
  static unsigned checked(Int lanes) {
    if (lanes < 1 || static_cast<unsigned long long>(lanes) > kMax) {
      throw std::invalid_argument("lane count " + std::to_string(lanes) + " is out of range: a design has at least one lane and at most " +
                                  std::to_string(kMax) + " (the CONFIG register holds 8 bits)");
    }
    return static_cast<unsigned>(lanes);
  }
  unsigned lanes_;
};

}  // namespace rc::board
