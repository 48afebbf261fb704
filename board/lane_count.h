// How many pipeline lanes (pipeline instances) a design has, valid by construction
// (board/checked_count.h): at least one, and at most 255, what the wrapper's CONFIG register can
// hold (register_map.h: lanes [7:0]). Every command, study file and profile key reads this bound.
#pragma once

#include <string_view>

#include "board/checked_count.h"

namespace rc::board {

struct LaneCountTag {
  static constexpr std::string_view what = "lane count";
  static constexpr std::string_view why = "a design's lanes; the CONFIG register holds 8 bits of the count";
};
using LaneCount = CheckedCount<LaneCountTag, 1, 255>;

}  // namespace rc::board
