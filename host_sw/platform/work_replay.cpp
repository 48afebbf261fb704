#include "host_sw/platform/work_replay.h"

#include <stdexcept>
#include <string>

#include "host_sw/driver/timing_replay_target.h"

namespace rc {

// Mirrors ProgressiveRadiosity::run and shoot: the charges, the visibility calls and their order.
void replay_host_work(const VisibilityRecording& recording, const ReplayShape& shape, HostCostSink& host,
                      TimingReplayTarget* board) {
  if (shape.steps < 0 || static_cast<std::size_t>(shape.steps) > recording.steps()) {
    throw std::invalid_argument("the recording has " + std::to_string(recording.steps()) + " steps, " +
                                std::to_string(shape.steps) + " were asked for");
  }
  auto charge = [&](HostWork work, std::uint64_t count) {
    if (count) host.charge(work, count);
  };
  charge(HostWork::PatchScan, shape.patches);
  for (int step = 0; step < shape.steps; ++step) {
    const std::size_t segments = recording.segments(step);
    charge(HostWork::SegmentSetup, segments);
    if (board != nullptr) board->submit_timing_only(segments, recording.source_face(step));
    charge(HostWork::FormFactor, segments);
    if (board != nullptr) {
      board->collect_timing_only();
    } else {
      charge(HostWork::IntersectionTest, recording.brute_force_tests(step));
    }
    // The host's own re-tests (the neighbour rule, SolverOptions::fixes), as the solver charges them
    // after the answer, whoever gave it.
    charge(HostWork::IntersectionTest, recording.host_tests(step));
    charge(HostWork::EnergyUpdate, recording.needed(step) - recording.blocked(step));
    charge(HostWork::Step, 1);
    charge(HostWork::PatchScan, shape.patches);
  }
}

}  // namespace rc
