// The pure parts of the several-card driver (host_sw/driver/multi_card_visibility.h): how work is shared out
// and how the split is named. The driver threads themselves run in tests/host_sw/platform/multi_card_test.cpp.
#include <gtest/gtest.h>

#include "host_sw/driver/multi_card_visibility.h"

namespace rc {
namespace {

// Contiguous and balanced: 70 faces on 2 cards are 0..34 and 35..69; 10 segments on 3 cards 3, 3, 4;
// fewer items than cards leave some cards empty.
TEST(CardShare, ContiguousAndBalanced) {
  EXPECT_EQ(card_share(70, 2, 0).first, 0u);
  EXPECT_EQ(card_share(70, 2, 0).count, 35u);
  EXPECT_EQ(card_share(70, 2, 1).first, 35u);
  EXPECT_EQ(card_share(70, 2, 1).count, 35u);
  std::size_t next = 0;
  for (unsigned c = 0; c < 3; ++c) {
    const CardShare s = card_share(10, 3, c);
    EXPECT_EQ(s.first, next);
    EXPECT_EQ(s.count, c < 2 ? 3u : 4u);
    next += s.count;
  }
  EXPECT_EQ(next, 10u);
  EXPECT_EQ(card_share(1, 4, 0).count, 0u);
  EXPECT_EQ(card_share(1, 4, 3).count, 1u);
  EXPECT_THROW(card_share(5, 2, 2), std::invalid_argument);
}

TEST(CardSplit, NamedChoices) {
  EXPECT_EQ(parse_choice<CardSplit>("rays"), CardSplit::rays);
  EXPECT_EQ(parse_choice<CardSplit>("faces"), CardSplit::faces);
  EXPECT_EQ(choice_name(CardSplit::faces), "faces");
  EXPECT_THROW(parse_choice<CardSplit>("segments"), std::invalid_argument);
}

}  // namespace
}  // namespace rc
