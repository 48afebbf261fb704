// The concurrent column's pipelined-driver mechanisms (docs/calibration.md, "The concurrent column"):
// the chunk rule on a recording, and the split it is combined with.
#include <gtest/gtest.h>

#include <cstdint>
#include <stdexcept>
#include <vector>

#include "host_sw/studies/paper_prediction.h"

namespace rc {
namespace {

// A scene whose recording has one step per entry of `sizes` segments; the paper's `steps` of them replayed.
PaperScene scene_with_steps(const std::vector<std::size_t>& sizes, int steps) {
  PaperScene s;
  s.row.faces = 70;
  s.row.patches = 280;
  s.row.steps = steps;
  for (std::size_t n : sizes) s.functional.recording.add_step(std::vector<std::uint8_t>(n, 0), {}, 0, 70 * n);
  return s;
}

TEST(PaperMechanisms, ChunkIsHalfTheLargestReplayedStepRoundedUp) {
  EXPECT_EQ(kPipelinedChunksPerStep, 2u);
  EXPECT_EQ(pipelined_chunk_rays(scene_with_steps({279, 279, 279}, 3)), 140u);  // 279 / 2 = 139.5
  EXPECT_EQ(pipelined_chunk_rays(scene_with_steps({4479, 4476}, 2)), 2240u);
  EXPECT_EQ(pipelined_chunk_rays(scene_with_steps({8, 13, 12}, 3)), 7u);  // the largest step, 13
  // Only the paper's steps are replayed: a larger step recorded beyond them does not count.
  EXPECT_EQ(pipelined_chunk_rays(scene_with_steps({8, 13, 12}, 1)), 4u);
  EXPECT_EQ(pipelined_chunk_rays(scene_with_steps({1}, 1)), 1u);
  // Every step then goes in at most two chunks, the largest in exactly two (when it has two segments).
  for (std::size_t n : {2u, 3u, 279u, 1119u, 4479u, 4480u}) {
    const std::uint64_t chunk = pipelined_chunk_rays(scene_with_steps({n, n / 2}, 2));
    EXPECT_EQ((n + chunk - 1) / chunk, 2u) << n << " segments";
    EXPECT_EQ((n / 2 + chunk - 1) / chunk, n / 2 > 0 ? 1u : 0u) << n / 2 << " segments";
  }
}

TEST(PaperMechanisms, AStepWithNoSegmentsHasNoChunk) {
  EXPECT_THROW(pipelined_chunk_rays(scene_with_steps({0, 0}, 2)), std::invalid_argument);
  EXPECT_THROW(pipelined_chunk_rays(scene_with_steps({}, 2)), std::invalid_argument);
}

TEST(PaperMechanisms, PipelinedAloneAndWithTheSplitOnTheSecondAthlon) {
  const std::vector<CpuSplit> splits = pipelined_splits();
  ASSERT_EQ(splits.size(), 2u);
  EXPECT_FALSE(splits[0].on());
  EXPECT_EQ(splits[1], parse_cpu_split("balanced", 2));
  DriverModel m;
  m.chunk_rays = 1120;
  m.cpu_split = splits[1];
  EXPECT_EQ(m.name(), "per_segment/dma/once/form_factors/cpu balanced on 2 cpus/chunks of 1120");
}

}  // namespace
}  // namespace rc
