#include <gtest/gtest.h>

#include <stdexcept>

#include "host_sw/studies/sweep_config.h"
#include "host_sw/studies/sweep_options.h"
#include "tests/host_sw/studies/sweep_test_support.h"

namespace rc {
namespace {

using namespace sweep_test;

TEST(SweepConfigs, EnumeratesDeviceWidthDriverLanesBanksInOrder) {
  SweepAxes a;
  a.devices = {"virtex4-sx55", "xc2v6000"};  // as given, not sorted
  a.bits = {15, 19};
  a.concurrent = {false, true};
  a.lanes = {1, 2};
  a.banks = {5, 6, 7};
  const std::vector<SweepConfig> c = enumerate_configs(a);
  ASSERT_EQ(c.size(), 2u * 2 * 2 * 2 * 3);
  EXPECT_EQ(c[0].label(), "virtex4-sx55 15-bit serial 1 lane 5 banks");
  EXPECT_EQ(c[1].label(), "virtex4-sx55 15-bit serial 1 lane 6 banks");
  EXPECT_EQ(c[3].label(), "virtex4-sx55 15-bit serial 2 lanes 5 banks");
  EXPECT_EQ(c[6].label(), "virtex4-sx55 15-bit concurrent 1 lane 5 banks");
  EXPECT_EQ(c[12].label(), "virtex4-sx55 19-bit serial 1 lane 5 banks");
  EXPECT_EQ(c[24].label(), "xc2v6000 15-bit serial 1 lane 5 banks");
  EXPECT_EQ(c.back().label(), "xc2v6000 19-bit concurrent 2 lanes 7 banks");
  // The same axes give the same list.
  const std::vector<SweepConfig> again = enumerate_configs(a);
  for (std::size_t i = 0; i < c.size(); ++i) EXPECT_EQ(c[i].label(), again[i].label());
}

TEST(SweepConfigs, RefusesEmptyAxesAndRunawaySweeps) {
  SweepAxes a;
  a.devices = {"xc2v6000"};
  a.bits = {15};
  a.concurrent = {true};
  a.lanes = {};
  a.banks = {6};
  EXPECT_THROW(enumerate_configs(a), std::invalid_argument);
  a.lanes = parse_int_list("1-255", "--lanes", 1, 255);
  a.banks = parse_int_list("1-255", "--banks", 1, 255);
  EXPECT_THROW(enumerate_configs(a), std::invalid_argument);
}

}  // namespace
}  // namespace rc
