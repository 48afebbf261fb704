// Several RC2000 cards in one board run (docs/board.md, "Several cards"): how many, how a step's
// work is split over them (host_sw/driver/multi_card_visibility.h) and how they sit on PCI.
#pragma once

#include <stdexcept>
#include <string>
#include <type_traits>

#include "host_sw/driver/multi_card_visibility.h"

namespace rc {

// How many cards, valid by construction: 1..16 (a host has few PCI slots; 16 is already far beyond
// a dual-processor host's driver threads). Checked once, when a number becomes a CardCount
// (std::invalid_argument naming it and the range); the conversion is implicit on purpose, as
// board::LaneCount's.
class CardCount {
 public:
  static constexpr unsigned kMax = 16;

  template <class Int, std::enable_if_t<std::is_integral_v<Int>, int> = 0>
  CardCount(Int cards) : cards_(checked(cards)) {}  // NOLINT(google-explicit-constructor): checked conversion
  constexpr operator unsigned() const { return cards_; }  // NOLINT(google-explicit-constructor)
  constexpr unsigned value() const { return cards_; }

 private:
  template <class Int>
  static unsigned checked(Int cards) {
    if (cards < 1 || static_cast<unsigned long long>(cards) > kMax) {
      throw std::invalid_argument("card count " + std::to_string(cards) + " is out of range: a board run has 1 to " +
                                  std::to_string(kMax) + " cards");
    }
    return static_cast<unsigned>(cards);
  }
  unsigned cards_;
};

// shared: every card on one PCI bus (their transfers serialise through one arbitration);
// separate: each card behind its own bridge, on its own bus segment (no contention).
enum class CardBus { shared, separate };

}  // namespace rc

template <>
struct rc::ChoiceNames<rc::CardBus> {
  static constexpr std::string_view what = "card bus";
  static constexpr std::array<std::string_view, 2> names = {"shared", "separate"};
};
