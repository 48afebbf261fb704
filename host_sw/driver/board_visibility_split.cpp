// The CPU/FPGA split's part of the RC2000 driver (host_sw/driver/cpu_split.h; docs/board.md, "CPU/FPGA
// split"): how many of a step's segments the host tests, where and when their tests are charged, their
// answers from the host kernel, and the board part's costs measured for the next balanced step.
#include <algorithm>

#include "host_sw/driver/board_visibility.h"

namespace rc {

std::size_t BoardVisibility::cpu_segments_of(std::size_t segments) const {
  const CpuSplit& split = options_.cpu_split;
  switch (split.mode) {
    case CpuSplit::Mode::off: return 0;
    case CpuSplit::Mode::fixed: return fixed_cpu_segments(segments, split.share);
    case CpuSplit::Mode::balanced: break;
  }
  const double test = cpu_.profile().work[static_cast<int>(HostWork::IntersectionTest)].to_seconds();
  return balanced_cpu_segments(segments, test * static_cast<double>(faces_.size()),
                               split.cores == 1 ? pass_seconds_per_segment_ : board_seconds_per_segment_);
}

bool BoardVisibility::second_cpu() const {
  return dual_cpu() || (options_.cpu_split.on() && options_.cpu_split.cores == 2);
}

// The step's split; on two processors the second starts its tests now (after any it still has).
void BoardVisibility::begin_step(std::size_t segments) {
  total_rays_ = segments;
  cpu_rays_ = cpu_segments_of(segments);
  step_start_ = cpu_.now();
  fpga_before_ = stats_.fpga_busy;
  stats_.cpu_segments += cpu_rays_;
  stats_.cpu_tests += std::uint64_t(cpu_rays_) * faces_.size();
  if (second_cpu()) cpu_.fork_second_cpu(dual_cpu());
  if (options_.cpu_split.cores == 2) charge_cpu_part();
}

void BoardVisibility::charge_cpu_part() {
  const std::uint64_t tests = std::uint64_t(cpu_rays_) * faces_.size();
  if (tests == 0) return;
  if (options_.cpu_split.cores == 2) {
    cpu_.charge_second_cpu(HostWork::IntersectionTest, tests);
  } else {
    cpu_.charge(HostWork::IntersectionTest, tests);
  }
}

// The CPU's segments are the last cpu_rays_ in end-face order (the board's stay one contiguous run
// for its own-surface table): the oracle's answer, or the host kernel's on those segments alone.
void BoardVisibility::answer_cpu_part(const SegmentBatch& batch) {
  if (cpu_rays_ == 0) return;
  const std::size_t first = total_rays_ - cpu_rays_;
  if (options_.oracle != nullptr) {
    std::copy(oracle_answer_.begin() + static_cast<long>(first), oracle_answer_.end(),
              blocked_.begin() + static_cast<long>(first));
    return;
  }
  SegmentBatch part;
  part.start = batch.start;
  part.source_face = batch.source_face;
  for (std::size_t i = first; i < total_rays_; ++i) {
    part.ends.push_back(batch.ends[order_[i]]);
    part.end_faces.push_back(batch.end_faces[order_[i]]);
    if (!batch.needed.empty()) part.needed.push_back(batch.needed[order_[i]]);
  }
  std::vector<std::uint8_t> answer;
  options_.cpu_kernel->submit(part);
  options_.cpu_kernel->collect(answer);
  std::copy(answer.begin(), answer.end(), blocked_.begin() + static_cast<long>(first));
}

// What the next balanced step divides by: the board part's pass time and its whole time (from the
// step's start to the last result read), per segment.
void BoardVisibility::board_part_done() {
  if (rays_ == 0) return;
  const double n = static_cast<double>(rays_);
  pass_seconds_per_segment_ = (stats_.fpga_busy - fpga_before_).to_seconds() / n;
  board_seconds_per_segment_ = (cpu_.now() - step_start_).to_seconds() / n;
}

}  // namespace rc
