// A count valid by construction: a whole number Min..Max of some quantity (lanes, cards), checked
// once, when a number becomes the count (std::invalid_argument naming the quantity, the number and
// the bounds), so everything that takes one relies on it. The bounds live here, in the type: a
// command's option, a study file's axis and the library all read them from `kMin` and `kMax`.
// The conversion from any integer type is implicit on purpose, so each call site with a bare count
// is checked at the call; the value reads as unsigned.
//
// Tag names the quantity: `static constexpr std::string_view what` ("lane count") and `why` (where
// the bounds come from), e.g.
//   struct LaneTag { static constexpr std::string_view what = "lane count", why = "..."; };
//   using LaneCount = CheckedCount<LaneTag, 1, 255>;
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>

namespace rc::board {

template <class Tag, unsigned Min, unsigned Max>
class CheckedCount {
  static_assert(Min <= Max, "a count's bounds must be ordered");

 public:
  static constexpr unsigned kMin = Min;
  static constexpr unsigned kMax = Max;

  template <class Int, std::enable_if_t<std::is_integral_v<Int> && !std::is_same_v<Int, bool>, int> = 0>
  CheckedCount(Int n) : n_(checked(n)) {}  // NOLINT(google-explicit-constructor): checked conversion
  constexpr operator unsigned() const { return n_; }  // NOLINT(google-explicit-constructor)
  constexpr unsigned value() const { return n_; }

 private:
  template <class Int>
  static unsigned checked(Int n) {
    bool in_range = true;
    if constexpr (std::is_signed_v<Int>) in_range = n >= 0;
    in_range = in_range && static_cast<unsigned long long>(n) >= Min && static_cast<unsigned long long>(n) <= Max;
    if (!in_range) {
      throw std::invalid_argument(std::string(Tag::what) + " " + std::to_string(n) + " is out of range: at least " +
                                  std::to_string(Min) + " and at most " + std::to_string(Max) + " (" + std::string(Tag::why) + ")");
    }
    return static_cast<unsigned>(n);
  }
  unsigned n_;
};

}  // namespace rc::board
