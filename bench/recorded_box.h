// The workload the systems benchmarks replay: the Cornell Box refined to 70 faces and split into 280
// patches, solved for a fixed number of shooting steps by the culled 15-bit kernel once, its
// recording kept (host_sw/studies/timing_study.h). bench_systems and bench_replay_floor time
// SystemC replays of it; one definition, so both measure the same work.
#pragma once

#include "host_sw/studies/timing_study.h"
#include "scenes/prepare.h"

namespace rc::bench {

struct RecordedBox {
  Scene scene;
  SolverOptions solver;
  RecordedRun recorded;
};

// Made once per process and step count (the solve takes a fraction of a second at 40 steps).
inline RecordedBox record_box(int steps) {
  RecordedBox made;
  SceneOptions options;
  options.face_target = 70;
  options.face_levels = 0;
  options.patch_levels = 1;
  made.scene = prepare_scene(options).scene;
  made.solver.fixed_steps = steps;
  made.recorded = record_functional_run(made.scene, made.solver, "fast", 15, 1);
  return made;
}

}  // namespace rc::bench
