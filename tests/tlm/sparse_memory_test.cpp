// SparseMemory: pages on first touch, zeros without allocation, any capacity up to 2^64 - 1 bytes.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <limits>
#include <numeric>
#include <stdexcept>

#include "tlm/sparse_memory.h"

namespace rc::tlmx::test {
namespace {

constexpr std::uint64_t kMax = std::numeric_limits<std::uint64_t>::max();

TEST(SparseMemory, UntouchedMemoryReadsZeroAndAllocatesNothing) {
  SparseMemory memory(1u << 20, 4096);
  std::array<std::uint8_t, 8192> out;
  out.fill(0xEE);
  memory.read(4000, out.data(), out.size());  // three pages, none touched
  for (std::uint8_t b : out) ASSERT_EQ(b, 0);
  EXPECT_EQ(memory.find_page(4000), nullptr);
  EXPECT_EQ(memory.pages_allocated(), 0u);
}

TEST(SparseMemory, WritesAllocateOnlyThePagesTheyTouch) {
  SparseMemory memory(1u << 20, 4096);
  std::array<std::uint8_t, 200> in;
  std::iota(in.begin(), in.end(), 1);
  memory.write(4000, in.data(), in.size());  // 96 bytes in page 0, 104 in page 1
  EXPECT_EQ(memory.pages_allocated(), 2u);
  EXPECT_NE(memory.find_page(0), nullptr);
  EXPECT_NE(memory.find_page(4096), nullptr);
  EXPECT_EQ(memory.find_page(8192), nullptr);
  std::array<std::uint8_t, 204> out{};
  memory.read(3998, out.data(), out.size());
  EXPECT_EQ(out[0], 0);
  EXPECT_EQ(out[1], 0);
  for (std::size_t i = 0; i < in.size(); ++i) ASSERT_EQ(out[i + 2], in[i]) << i;
  EXPECT_EQ(out[202], 0);
  EXPECT_EQ(memory.page(4100), memory.find_page(4096));  // page() hands out the same storage
  EXPECT_EQ(memory.pages_allocated(), 2u);
}

TEST(SparseMemory, PagesAreAlignedAndTheLastIsCutAtTheCapacity) {
  SparseMemory memory(10000, 4096);
  EXPECT_EQ(memory.page_start(5000), 4096u);
  EXPECT_EQ(memory.page_last(5000), 8191u);
  EXPECT_EQ(memory.page_start(9999), 8192u);
  EXPECT_EQ(memory.page_last(9999), 9999u);
  const std::uint8_t one = 1;
  memory.write(9999, &one, 1);
  EXPECT_EQ(memory.find_page(8192)[9999 - 8192], 1);
}

// The page table is a hash map: a store of the whole 64-bit space costs only what it holds.
TEST(SparseMemory, TheWholeAddressSpaceCostsOnlyItsTouchedPages) {
  SparseMemory memory(kMax, 1u << 16);
  const std::uint64_t top = kMax - 1;  // the last valid address
  EXPECT_EQ(memory.page_last(top), top);
  const std::array<std::uint8_t, 4> word{1, 2, 3, 4};
  memory.write(top - 3, word.data(), 4);
  memory.write(0, word.data(), 4);
  std::array<std::uint8_t, 4> back{};
  memory.read(top - 3, back.data(), 4);
  EXPECT_EQ(back, word);
  EXPECT_EQ(memory.pages_allocated(), 2u);
}

TEST(SparseMemory, PageSizeMustBeAPowerOfTwo) {
  EXPECT_THROW(SparseMemory(4096, 0), std::invalid_argument);
  EXPECT_THROW(SparseMemory(4096, 3000), std::invalid_argument);
  EXPECT_EQ(SparseMemory(4096, 1).page_bytes(), 1u);
}

}  // namespace
}  // namespace rc::tlmx::test
