// Timing replay of a recorded run: the host charges exactly the work the solver charged, step by
// step and in the same order (host_sw/radiosity/radiosity.cpp), and the board (if any) runs the same passes
// without data. The solver is not run again and visibility is not recomputed, so a timing
// configuration costs only its simulated events. Tests prove the times equal a real run's.
#pragma once

#include <cstddef>

#include "host_sw/radiosity/host_cost.h"
#include "host_sw/visibility/visibility_recording.h"

namespace rc {

class TimingReplayTarget;  // host_sw/driver/timing_replay_target.h: one card's driver or several cards'

struct ReplayShape {
  std::size_t patches = 0;  // the solver scans every patch to choose each shooter
  int steps = 0;            // steps to replay (a prefix of the recording)
};

// With `board` null the tests are the host's (the software implementation): each step charges
// the recorded brute-force test count; either way the host also charges the recording's host tests
// (the neighbour rule's re-tests) as intersection tests, as the solver does. Throws std::invalid_argument if the recording is too short.
// Call from the host SC_THREAD; the board's faces must already be loaded.
void replay_host_work(const VisibilityRecording& recording, const ReplayShape& shape, HostCostSink& host,
                      TimingReplayTarget* board);

}  // namespace rc
