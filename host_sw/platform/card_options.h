// Several RC2000 cards in one board run (docs/board.md, "Several cards"): how many, how a step's
// work is split over them (host_sw/driver/multi_card_visibility.h) and how they sit on PCI.
#pragma once

#include <array>
#include <string_view>

#include "board/checked_count.h"
#include "host_sw/driver/multi_card_visibility.h"

namespace rc {

// How many cards, valid by construction (board/checked_count.h): 1..16 (a host has few PCI slots;
// 16 is already far beyond a dual-processor host's driver threads).
struct CardCountTag {
  static constexpr std::string_view what = "card count";
  static constexpr std::string_view why = "a board run's cards; a host has few PCI slots";
};
using CardCount = board::CheckedCount<CardCountTag, 1, 16>;

// shared: every card on one PCI bus (their transfers serialise through one arbitration);
// separate: each card behind its own bridge, on its own bus segment (no contention).
enum class CardBus { shared, separate };

}  // namespace rc

template <>
struct rc::ChoiceNames<rc::CardBus> {
  static constexpr std::string_view what = "card bus";
  static constexpr std::array<std::string_view, 2> names = {"shared", "separate"};
};
