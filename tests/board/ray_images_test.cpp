// The host's and the wrapper's per-pass shortcuts on the ray split (board/bank_layout.h, word_format.h)
// against what they replace: RaySplitMemo (the last two ray counts) returns split_rays of the count
// asked for in any order of counts, and a split it returned stays valid through the next call;
// size_ray_images gives every bank the size blank_ray_images does, whatever the images held before.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "board/bank_layout.h"
#include "board/word_format.h"

namespace rc::board {
namespace {

void expect_same_split(const RaySplit& a, const RaySplit& b) {
  EXPECT_EQ(a.rays, b.rays);
  EXPECT_EQ(a.first_ray, b.first_ray);
  EXPECT_EQ(a.packets, b.packets);
  EXPECT_EQ(a.result_base, b.result_base);
  EXPECT_EQ(a.result_words, b.result_words);
  EXPECT_EQ(a.fits, b.fits);
}

// Alternating counts (a pipelined step's full and last chunk), repeats, a third count, zero.
const std::vector<std::uint64_t> kCounts = {100, 37, 100, 37, 37, 5, 100, 5, 5, 0, 100, 1, 0, 4000};

TEST(RaySplitMemo, EveryCountIsSplitRaysAndTheLastStaysValid) {
  for (unsigned lanes : {1u, 2u, 3u, 4u}) {
    const BankLayout layout = make_bank_layout(LaneCount(lanes), 6, 15, 32, 4u << 20);
    RaySplitMemo memo(layout);
    const RaySplit* previous = nullptr;
    RaySplit previous_copy;
    for (std::uint64_t rays : kCounts) {
      SCOPED_TRACE(std::to_string(lanes) + " lanes, " + std::to_string(rays) + " rays");
      const RaySplit& split = memo(rays);
      expect_same_split(split, split_rays(layout, rays));
      if (previous != nullptr) expect_same_split(*previous, previous_copy);  // not overwritten by this call
      previous = &split;
      previous_copy = split;
    }
  }
}

TEST(RayImages, SizedAsBlankOnesWhateverTheyHeld) {
  for (unsigned lanes : {1u, 2u, 3u, 4u}) {
    const BankLayout layout = make_bank_layout(LaneCount(lanes), 6, 15, 32, 4u << 20);
    std::vector<std::vector<std::uint8_t>> sized, blank;
    for (std::uint64_t rays : kCounts) {
      SCOPED_TRACE(std::to_string(lanes) + " lanes, " + std::to_string(rays) + " rays");
      const RaySplit split = split_rays(layout, rays);
      size_ray_images(layout, split, sized);
      blank_ray_images(layout, split, blank);
      ASSERT_EQ(sized.size(), blank.size());
      ASSERT_EQ(sized.size(), layout.banks_available);
      for (std::size_t b = 0; b < blank.size(); ++b) EXPECT_EQ(sized[b].size(), blank[b].size()) << "bank " << b;
      for (auto& image : sized) std::fill(image.begin(), image.end(), std::uint8_t{0xA5});  // what a pack left
    }
  }
}

}  // namespace
}  // namespace rc::board
