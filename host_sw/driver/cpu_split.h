// The CPU/FPGA split of a step's visibility work (issue 28; docs/board.md, "CPU/FPGA split"): the
// driver gives some of each step's segments to software tests on the host's processor(s) and the
// rest to the board. The answers come from a host kernel bit-identical to the lanes (the fixed-point
// pipeline at the board's width, or the float lanes' format), so radiosity does not depend on the
// split; only the time does. Software tests cost the host profile's calibrated
// work_seconds.intersection_test each, every segment against every face (what the software column
// pays per segment).
//
//   cores 1: the solver's processor tests its share between the step's first START and the wait,
//            while the board works (then, in concurrent mode, computes the form factors);
//   cores 2: the second Athlon of the dual-processor host (paper sec 5.4) tests its share from the
//            moment the segments reach the driver; the step waits for both.
//
// The share is fixed, or balanced per step from what the driver measured on its previous step:
// cores 1 matches the CPU's tests to the board's pass time, cores 2 to the whole board part
// (packing, transfers, passes, results). The first step, with nothing measured, goes to the board.
#pragma once

#include <cstddef>
#include <string>

namespace rc {

struct CpuSplit {
  enum class Mode { off, fixed, balanced } mode = Mode::off;
  double share = 0;    // fixed: the fraction of each step's segments the CPU tests, 0..1
  unsigned cores = 1;  // 1 or 2 (see above)

  bool on() const { return mode != Mode::off; }
  std::string name() const;  // "off", "0.25 on 1 cpu", "balanced on 2 cpus"
  bool operator==(const CpuSplit& other) const;
};

// "--cpu-share" text: a number 0..1 or "balanced"; cores 1 or 2. Throws std::invalid_argument naming
// the option and its limits.
CpuSplit parse_cpu_split(const std::string& share, unsigned cores);

// The segments of a step of `segments` the CPU tests under a fixed share: share x segments, rounded
// to the nearest (halves up).
std::size_t fixed_cpu_segments(std::size_t segments, double share);

// Under a balanced split: k with k x cpu = (segments - k) x board, to the nearest segment (halves
// up), from each side's seconds per segment. Nothing measured yet (board <= 0): 0.
std::size_t balanced_cpu_segments(std::size_t segments, double cpu_seconds_per_segment,
                                  double board_seconds_per_segment);

}  // namespace rc
