#include <gtest/gtest.h>

#include "host_sw/studies/sweep_options.h"
#include "tests/host_sw/studies/sweep_test_support.h"

namespace rc {
namespace {

using namespace sweep_test;

TEST(SweepOptions, ParsesListsAndRangesAscendingAndDistinct) {
  EXPECT_EQ(parse_int_list("1-16", "--lanes", 1, 255), (std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16}));
  EXPECT_EQ(parse_int_list("15", "--bits", 7, 31), (std::vector<int>{15}));
  EXPECT_EQ(parse_int_list("8, 5-6 ,6,12", "--banks", 1, 255), (std::vector<int>{5, 6, 8, 12}));
  EXPECT_EQ(parse_int_list("3-3", "--lanes", 1, 255), (std::vector<int>{3}));
}

TEST(SweepOptions, RejectsBadListsNamingTheOption) {
  for (const char* bad : {"", " ", "1,,2", "x", "1-", "-3", "4-2", "1-2-3", "1.5", "0", "256", "2-300", "1e3", "+4"}) {
    try {
      parse_int_list(bad, "--lanes", 1, 255);
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("--lanes"), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(parse_int_list("6", "--bits", 7, 31), std::invalid_argument);
}

TEST(SweepOptions, ParsesNamesDriversAndSteps) {
  EXPECT_EQ(parse_name_list("xc2v6000, virtex4-sx55,xc2v6000", "--devices"),
            (std::vector<std::string>{"xc2v6000", "virtex4-sx55"}));
  EXPECT_THROW(parse_name_list("a,,b", "--devices"), std::invalid_argument);
  EXPECT_THROW(parse_name_list("", "--devices"), std::invalid_argument);
  EXPECT_EQ(parse_concurrency("both"), (std::vector<bool>{false, true}));
  EXPECT_EQ(parse_concurrency("on"), (std::vector<bool>{true}));
  EXPECT_THROW(parse_concurrency("yes"), std::invalid_argument);
  EXPECT_EQ(parse_steps("paper").kind, StepsChoice::Kind::paper);
  EXPECT_EQ(parse_steps("converge").kind, StepsChoice::Kind::converge);
  EXPECT_EQ(parse_steps("1488").kind, StepsChoice::Kind::fixed);
  EXPECT_EQ(parse_steps("1488").steps, 1488);
  for (const char* bad : {"0", "-5", "many", "", "12x"}) EXPECT_THROW(parse_steps(bad), std::invalid_argument) << bad;
}

}  // namespace
}  // namespace rc
