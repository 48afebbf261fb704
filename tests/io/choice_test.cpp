// io/choice.h: one name list per choice, parsed and printed in one place.
#include "io/choice.h"

#include <gtest/gtest.h>

namespace rc {
namespace {

enum class Fruit { apple, pear, plum };

}  // namespace

template <>
struct ChoiceNames<Fruit> {
  static constexpr std::string_view what = "fruit";
  static constexpr std::array<std::string_view, 3> names = {"apple", "pear", "plum"};
};

namespace {

TEST(Choice, EveryNameParsesToItsEnumAndPrintsBack) {
  for (Fruit f : {Fruit::apple, Fruit::pear, Fruit::plum}) {
    EXPECT_EQ(parse_choice<Fruit>(choice_name(f)), f);
  }
  EXPECT_EQ(parse_choice<Fruit>("pear"), Fruit::pear);
  EXPECT_EQ(choice_name(Fruit::plum), "plum");
  EXPECT_EQ(choice_names<Fruit>(), (std::vector<std::string>{"apple", "pear", "plum"}));
  EXPECT_EQ(choice_name_list<Fruit>(), "apple, pear, plum");
}

TEST(Choice, AnUnknownNameIsRefusedNamingItAndEveryChoice) {
  for (const char* bad : {"", "Apple", "apple ", "fig", "pear,plum"}) {
    try {
      (void)parse_choice<Fruit>(bad);
      ADD_FAILURE() << bad;
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()), std::string("fruit '") + bad + "' is not one of: apple, pear, plum");
    }
  }
}

}  // namespace
}  // namespace rc
