// What a timing replay (host_sw/platform/work_replay.h) drives on the board side: the passes, transfers,
// registers, interrupts and driver work of one step of `segments` segments from `source_face`,
// without the data. One card (BoardVisibility) or several (MultiCardVisibility) alike.
#pragma once

#include <cstddef>

namespace rc {

class TimingReplayTarget {
 public:
  virtual ~TimingReplayTarget() = default;
  virtual void submit_timing_only(std::size_t segments, int source_face) = 0;
  virtual void collect_timing_only() = 0;
};

}  // namespace rc
