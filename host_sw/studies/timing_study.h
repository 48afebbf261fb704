// Many timing configurations of one functional answer, in one simulation. Visibility is computed
// once per scene and width (a recording); every configuration (software, lanes, banks, device,
// concurrency, host profile) replays it through its own SystemC system. SystemC elaborates once per
// process, so all systems are elaborated side by side and run by a single sc_start; they share
// nothing, so each one's simulated time is what it would be alone.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "host_sw/platform/board_run.h"
#include "host_sw/radiosity/radiosity.h"
#include "host_sw/visibility/visibility_recording.h"
#include "scenes/scene.h"

namespace rc {

// A functional run whose answers are kept for replay.
struct RecordedRun {
  SolverResult result;
  VisibilityRecording recording;
  int convergence_step = 0;  // first step at which the convergence target was met (0: not within the run)
};

// Solves with a software backend ("fixed", "fast", ...) at `bits`, recording every step.
// `threads`: the backend's own threads (fast only; 0 = jobs(), host_sw/radiosity/jobs.h).
RecordedRun record_functional_run(const Scene& scene, const SolverOptions& solver, const std::string& backend, int bits,
                                  int threads = 0);

struct TimingCase {
  std::string label;
  const Scene* scene = nullptr;
  SolverOptions solver;
  const VisibilityRecording* recording = nullptr;
  bool software = false;                // the software-only implementation (host CPU tests every segment)
  BoardRunOptions board;                // the board implementation (its oracle is the replay)
  std::string host = "athlon-mp-2600";  // host profile of a software case (board cases: board.host)
  std::optional<HostProfile> host_profile;  // when set, a software case's profile instead of `host`
};

unsigned default_study_processes();  // jobs() (host_sw/radiosity/jobs.h): --jobs, RC2000SIM_JOBS or the usable cores

// The most systems one process elaborates. Simulated side by side, systems take turns at every
// event, so a process cycles through all of their state: past about a hundred systems that state
// no longer fits the caches and the time per system grows (measured: 1.2 ms of sc_start per
// system at 100 systems, 5.3 ms at 1,000, for the same instructions; docs/results/performance.md).
// Larger studies are cut into shards of at most this many, each run in a process of its own.
inline constexpr std::size_t kMaxSystemsPerProcess = 64;

// How many shards run_timing_study cuts `cases` into: one per process (at most one per case) when
// every shard then holds at most kMaxSystemsPerProcess; otherwise the fewest that do, rounded up to
// a whole number of rounds of `processes` (3 shards on 2 cores would run the third alone while a
// core idles: 171 systems of `rc2000sim paper` made 4 shards of about 43, not 3 of 57).
std::size_t study_shards(std::size_t cases, unsigned processes);

struct TimingOutcome {
  std::string label;
  double simulated_seconds = 0;
  int steps = 0;
  RunReport report;  // the system's report (to_json: rc2000sim.board/1 or rc2000sim.software/1)
};

// Throws std::invalid_argument for a bad case (before elaboration) and rethrows a system's error.
// May be called once per process, before anything else elaborates SystemC.
//
// The cases are dealt to shards (largest first onto the least loaded), as many as `processes`
// and as many more as keep every shard within kMaxSystemsPerProcess; a SystemC kernel is
// single-threaded and elaborates once per process, so each shard elaborates in a process of its
// own. When the shards are no more than `processes`, this process runs the first and forked
// children the others; otherwise every shard runs in a forked child, `processes` at a time. Cases
// share nothing, so every outcome is what it would be in one process: the children send their
// reports back as JSON, which keeps every number exactly, and the result is in case order whatever
// the deal (tests TimingStudy.ProcessesChangeNoOutcome, TimingStudy.ShardsChangeNoOutcome).
std::vector<TimingOutcome> run_timing_study(const std::vector<TimingCase>& cases,
                                            unsigned processes = default_study_processes());

}  // namespace rc
