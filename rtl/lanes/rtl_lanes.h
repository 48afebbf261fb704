// The RTL lanes: board::ClockedLanes over the Verilated pipeline (rtl/sim), one model per lane, for the
// cycle-level wrapper to clock (board/clocked_lanes.h). The application wires them in
// (`rc2000sim run --impl board --lanes-impl rtl`; docs/board.md, "RTL lanes").
#pragma once

#include "board/clocked_lanes.h"

namespace rc::rtl {

// Named "rtl". Its make() throws std::invalid_argument when the build has no Verilated model at the
// width (rtl_unavailable_reason).
board::ClockedLanesFactory rtl_lanes_factory();

}  // namespace rc::rtl
