// Lanes whose arithmetic lives outside board/, clocked by the cycle-level wrapper (cycle_wrapper.h) one
// rising edge per device cycle, as its C++ lanes are: the RTL lanes (rtl/lanes: a Verilated model of
// rtl/mt_pipeline.v per lane) plug in here. board/ knows only this interface; the application wires an
// implementation in through BoardChoices::clocked_lanes (docs/board.md, "RTL lanes").
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "pipeline/fixed_format.h"

namespace rc::board {

// What one lane's input ports carry in one cycle.
struct ClockedLaneInput {
  bool valid = false;
  pipeline::FixedVec3 start{0, 0, 0}, end{0, 0, 0};
  pipeline::FaceRecord face{};
  // The guard band on t (T_GUARD [7:0], the same for every test of a pass): a static input port of
  // the lane, not a pipelined one (rtl/mt_pipeline.v's t_guard).
  int t_guard = 0;
};

class ClockedLanes {
 public:
  virtual ~ClockedLanes() = default;
  virtual unsigned lanes() const = 0;
  // One rising edge: lane i samples inputs[i] (inputs.size() == lanes()).
  virtual void clock_edge(const std::vector<ClockedLaneInput>& inputs) = 0;
  // Lane i's output ports after the last edge: a result leaves with out_valid high exactly `latency`
  // edges after the edge that sampled its input, minus one (it is sampled at the latency-th edge).
  virtual bool out_valid(unsigned lane) const = 0;
  virtual bool out_hit(unsigned lane) const = 0;
};

// Makes the lanes of one board: `lanes` lanes at `bits` fractional bits. Throws std::invalid_argument
// when it cannot (a width it was not built for, no Verilator in the build, ...).
struct ClockedLanesFactory {
  std::string name;  // e.g. "rtl": what the run reports
  std::function<std::unique_ptr<ClockedLanes>(unsigned lanes, pipeline::FracBits bits)> make;
  explicit operator bool() const { return static_cast<bool>(make); }
};

}  // namespace rc::board
