// own_surface_end (the sum read_inputs checks every pass against its rays) against the face-by-face
// walk of OwnSurfaceRange it replaces there: random tables with sheets of several faces, both word
// sizes, a first entry marked as continuing a sheet (the walk takes it anyway).
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "board/wrapper_base.h"

namespace rc::board {
namespace {

std::uint64_t walked_end(const std::vector<std::uint32_t>& entries, std::uint64_t mask_start) {
  OwnSurfaceRange walk(mask_start);
  for (std::size_t f = 0; f < entries.size(); ++f) walk.advance(entries[f], f == 0);
  return walk.next;
}

std::vector<std::uint8_t> in_words(const std::vector<std::uint32_t>& entries, unsigned word_bytes) {
  std::vector<std::uint8_t> bytes(entries.size() * word_bytes);
  for (std::size_t f = 0; f < entries.size(); ++f) store_word(bytes.data(), f, word_bytes, entries[f]);
  return bytes;
}

TEST(OwnSurfaceTable, EndIsWhereTheWalkEnds) {
  std::mt19937_64 random(29);
  std::uniform_int_distribution<std::uint32_t> rays(0, reg::kSheetRays);
  std::uniform_int_distribution<std::uint32_t> small(0, 300);
  int checked = 0;
  for (int table = 0; table < 400; ++table) {
    const std::size_t faces = table % 40;
    std::vector<std::uint32_t> entries(faces);
    for (std::uint32_t& e : entries) {
      e = (table % 2 ? rays(random) : small(random)) | (random() % 3 == 0 ? reg::kSameSheet : 0u);
    }
    const std::uint64_t mask_start = random() % 5000;
    for (unsigned word_bytes : {4u, 8u}) {
      const std::vector<std::uint8_t> words = in_words(entries, word_bytes);
      EXPECT_EQ(own_surface_end(words.data(), faces, word_bytes, mask_start), walked_end(entries, mask_start))
          << "table " << table << ", " << word_bytes << "-byte words";
      ++checked;
    }
  }
  EXPECT_EQ(checked, 800);
  // A one-sided table (no sheet continues): every count; a first entry marked continuing: counted.
  const std::vector<std::uint32_t> one_sided{3, 0, 7};
  EXPECT_EQ(own_surface_end(in_words(one_sided, 4).data(), 3, 4, 10), 20u);
  const std::vector<std::uint32_t> marked_first{reg::kSameSheet | 5, reg::kSameSheet | 9, 2};
  EXPECT_EQ(own_surface_end(in_words(marked_first, 8).data(), 3, 8, 0), 7u);
  EXPECT_EQ(walked_end(marked_first, 0), 7u);
}

}  // namespace
}  // namespace rc::board
