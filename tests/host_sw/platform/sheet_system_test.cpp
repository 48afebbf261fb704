// Two-sided surfaces on the board (docs/board.md, "Own-surface table"): the tilted plate of
// scenes/examples/tilted-plate.scene is one sheet of four faces. The board masks the shooter's whole
// sheet (SOURCE_FACE, SOURCE_FACES) and, for each face, the rays ending on its sheet (the own-surface
// table), so its answers are the CPU fixed-point backend's bit for bit: in one pass, when a face set
// ends inside the sheet, on the cycle-level model (same times), and on cards that each hold part of
// the sheet. A timing replay takes the functional run's time to the picosecond.
#include <gtest/gtest.h>

#include <memory>

#include "host_sw/platform/work_replay.h"
#include "host_sw/visibility/visibility_factory.h"
#include "host_sw/visibility/visibility_recording.h"
#include "scenes/prepare.h"
#include "tests/host_sw/platform/system_support.h"

namespace rc::test {
namespace {

// 16 faces: the room's 12, then the plate's sheet [12, 16).
Scene tilted_plate(int patch_levels) {
  SceneOptions o;
  o.file = RC_SOURCE_DIR "/scenes/examples/tilted-plate.scene";
  o.patch_levels = patch_levels;
  return prepare_scene(o).scene;
}

TEST(SheetSystem, ThePlateIsOneSheetOfFourFaces) {
  const Scene scene = tilted_plate(0);
  ASSERT_EQ(scene.faces.size(), 16u);
  EXPECT_EQ(scene.sheets.shared_sheets(), 1u);
  EXPECT_EQ(scene.sheets.first(15), 12);
  EXPECT_EQ(scene.sheets.size_of(13), 4);
}

// One pass per step, then face sets of 14 (the second set starts inside the sheet), on 2 lanes at
// 15 bits and 4 lanes at 7 bits: every radiosity bit is the CPU's.
TEST(SheetSystem, BoardIsBitIdenticalToCpuFixedPointWithSheetsSplitBySets) {
  const Scene scene = tilted_plate(1);
  const SolverOptions so = steps(40);
  BoardRunOptions o;
  o.lanes = 2;
  BoardSystem whole("whole", scene, so, setup(o));
  o.bank_capacity_bytes = 14 * 9 * 4;  // 14 face records per set (table in spare bank 5)
  BoardSystem split("split", scene, so, setup(o));
  BoardRunOptions narrow;
  narrow.lanes = 4;
  narrow.bits = 7;
  BoardSystem seven("seven", scene, so, setup(narrow));
  run_all({&whole, &split, &seven});

  EXPECT_EQ(split.board.layout().max_faces_per_set, 14u);
  EXPECT_EQ(split.driver().stats().face_sets, 2u);
  const SolverResult cpu15 = cpu_fixed_point(scene, so, 15);
  const SolverResult cpu7 = cpu_fixed_point(scene, so, 7);
  ASSERT_GT(cpu15.blocked_segments, 0u);
  expect_identical(whole.result().radiosity, cpu15.radiosity);
  expect_identical(split.result().radiosity, cpu15.radiosity);
  expect_identical(seven.result().radiosity, cpu7.radiosity);
  EXPECT_EQ(whole.result().blocked_segments, cpu15.blocked_segments);
  EXPECT_EQ(split.result().blocked_segments, cpu15.blocked_segments);
  EXPECT_EQ(seven.result().blocked_segments, cpu7.blocked_segments);
}

// The cycle-level wrapper streams the same table: same answers, same cycles, same bank traffic.
TEST(SheetSystem, CycleLevelModelMatchesFastModelOnSheets) {
  const Scene scene = tilted_plate(0);
  const SolverOptions so = steps(8);
  BoardRunOptions o;
  o.lanes = 2;
  BoardSystem fast("fast", scene, so, setup(o));
  o.model = board::WrapperModel::cycle;
  BoardSystem cycle("cycle", scene, so, setup(o));
  run_all({&fast, &cycle});
  expect_cycle_model_matches_fast(fast, cycle);
}

// Five cards splitting the faces 4, 3, 3, 3, 3: the sheet [12, 16) is cut between cards 3 and 4.
TEST(SheetSystem, CardsHoldingPartsOfASheetGiveOneCardsAnswer) {
  const Scene scene = tilted_plate(1);
  const SolverOptions so = steps(30);
  BoardRunOptions o;
  o.lanes = 2;
  o.cards = 5;
  o.card_split = CardSplit::faces;
  BoardSystem five("five", scene, so, setup(o));
  run_all({&five});
  const SolverResult cpu = cpu_fixed_point(scene, so, 15);
  expect_identical(five.result().radiosity, cpu.radiosity);
  EXPECT_EQ(five.result().blocked_segments, cpu.blocked_segments);
  EXPECT_EQ(five.multi_card()->faces(3), 3u);
}

// SOURCE_FACES is written only when the shooter's sheet size changes; a timing replay (which knows
// only each step's source face) writes it at the same steps, so it takes exactly the real run's time.
TEST(SheetSystem, TimingReplayTakesTheFunctionalRunsTime) {
  const Scene scene = tilted_plate(1);
  const SolverOptions so = steps(25);
  VisibilityRecording recording;
  {
    auto answer = make_functional_answer("fixed", 15);
    RecordingVisibility recorder(*answer, recording);
    ProgressiveRadiosity(scene, recorder, so).run();
  }
  bool sheet_shooter = false, face_shooter = false;
  for (std::size_t s = 0; s < recording.steps(); ++s) {
    (scene.sheets.size_of(recording.source_face(s)) > 1 ? sheet_shooter : face_shooter) = true;
  }
  EXPECT_TRUE(sheet_shooter && face_shooter) << "the steps must switch between sheet sizes";
  BoardRunOptions o;
  o.lanes = 2;
  BoardSystem real("real", scene, so, setup(o));
  BoardSetup replay_setup = setup(o);
  replay_setup.replay = &recording;
  BoardSystem replay("replay", scene, so, replay_setup);
  run_all({&real, &replay});
  EXPECT_EQ(real.end_time(), replay.end_time());
  EXPECT_EQ(real.board.regs.accesses(), replay.board.regs.accesses());
}

}  // namespace
}  // namespace rc::test
