// Not a test: a measurement, disabled so that ctest never runs it. Wall time per simulated step of
// the largest paper configuration (Table 2, last row: 1120 faces, 4480 patches), quoted in
// docs/board.md. Run it by hand on a Release build:
//
//   RC_MEASURE_STEPS=200 RC_MEASURE_LANES=2 build-board/tests/test_board
//       --gtest_also_run_disabled_tests --gtest_filter=BoardMeasure.DISABLED_LargestPaperScene
//   (one command line)
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>

#include "host_sw/platform/board_run.h"
#include "scenes/prepare.h"
#include "host_sw/outputs/run_report_json.h"

namespace rc {
namespace {

int env_int(const char* name, int fallback) {
  const char* v = std::getenv(name);
  return v != nullptr ? std::atoi(v) : fallback;
}

TEST(BoardMeasure, DISABLED_LargestPaperScene) {
  SceneOptions so;
  so.face_target = 70;
  so.face_levels = 2;   // 1120 faces
  so.patch_levels = 1;  // 4480 patches
  const auto t0 = std::chrono::steady_clock::now();
  const Scene scene = prepare_scene(so).scene;
  SolverOptions solver;
  solver.fixed_steps = env_int("RC_MEASURE_STEPS", 200);
  BoardRunOptions o;
  o.lanes = static_cast<unsigned>(env_int("RC_MEASURE_LANES", 2));
  o.concurrent = env_int("RC_MEASURE_CONCURRENT", 1) != 0;
  const BoardRunResult r = run_radiosity_on_board(scene, solver, o);
  const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("%zu faces, %zu patches, %d steps, %u lanes, %s: %llu segments, %.3g tests\n", scene.faces.size(),
              scene.patches.size(), r.solver.steps, o.lanes.value(), o.concurrent ? "concurrent" : "serial",
              static_cast<unsigned long long>(r.solver.segments), static_cast<double>(r.report.intersections.tests));
  std::printf("wall: %.3f s in sc_start, %.3f s with scene preparation; %.3f ms per simulated step\n",
              r.report.wall_seconds, total, 1e3 * r.report.wall_seconds_per_step);
  std::printf("simulated: %.6f s (%.3f ms per step)\n", r.report.simulated_seconds,
              1e3 * r.report.simulated_seconds / r.solver.steps);
  std::printf("%s\n", to_json(r.report).dump(2).c_str());
}

}  // namespace
}  // namespace rc
