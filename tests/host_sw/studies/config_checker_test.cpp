#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "board/bank_layout.h"
#include "host_sw/studies/config_checker.h"
#include "tests/host_sw/studies/sweep_test_support.h"

namespace rc {
namespace {

using namespace sweep_test;

TEST(ConfigChecker, TheRc2000ConfigurationsThePaperBuiltAreValid) {
  const ConfigChecker checker({"xc2v6000"}, kHost);
  for (unsigned lanes : {1u, 2u}) {
    const ConfigCheck c = checker.check(config("xc2v6000", lanes, 6));
    EXPECT_EQ(c.validity, Validity::ok) << c.reason;
    EXPECT_TRUE(c.reason.empty());
    EXPECT_EQ(c.options.lanes, lanes);
    EXPECT_EQ(c.options.banks, 6u);
    EXPECT_EQ(c.options.host, kHost);
    EXPECT_TRUE(c.options.concurrent);
    EXPECT_NO_THROW(make_board_setup(c.options));
  }
  EXPECT_NEAR(checker.check(config("xc2v6000", 1, 6)).clock_mhz, 53.833, 1e-9);  // sec 5.4
  EXPECT_NEAR(checker.check(config("xc2v6000", 2, 6)).clock_mhz, 52.5, 1e-9);    // sec 5.5
}

TEST(ConfigChecker, LanesThatDoNotFitTheDeviceAreReportedWithTheFitMessage) {
  const ConfigChecker checker({"xc2v6000"}, kHost);
  for (unsigned banks : {6u, 20u}) {  // enough banks or not: the fit is checked first
    const ConfigCheck c = checker.check(config("xc2v6000", 12, banks));
    EXPECT_EQ(c.validity, Validity::does_not_fit);
    EXPECT_NE(c.reason.find("does not fit"), std::string::npos) << c.reason;
    EXPECT_NE(c.reason.find("xc2v6000"), std::string::npos) << c.reason;
    EXPECT_EQ(c.clock_mhz, 0);
    BoardRunOptions o;
    o.lanes = 12;
    o.banks = banks;
    EXPECT_THROW(make_board_setup(o), std::invalid_argument);  // the same verdict as a run
  }
}

TEST(ConfigChecker, TooFewBanksIsReportedWhenTheLanesFit) {
  const ConfigChecker checker({"xc2v6000"}, kHost);
  // 15 bits: two lanes per word, so 8 lanes are 4 ray groups: 14 banks at full rate, 12 at least.
  const ConfigCheck six = checker.check(config("xc2v6000", 8, 6));
  EXPECT_EQ(six.validity, Validity::too_few_banks) << six.reason;
  EXPECT_NE(six.reason.find("the board has 6"), std::string::npos) << six.reason;
  EXPECT_GT(six.clock_mhz, 0);  // the design fits; only the banks are missing
  EXPECT_EQ(checker.check(config("xc2v6000", 8, 11)).validity, Validity::too_few_banks);
  EXPECT_EQ(checker.check(config("xc2v6000", 8, 12)).validity, Validity::ok);
  // Fewer than the basic architecture's five banks (sec 4.1).
  const ConfigCheck four = checker.check(config("xc2v6000", 1, 4));
  EXPECT_EQ(four.validity, Validity::too_few_banks);
  EXPECT_NE(four.reason.find("at least 5 banks"), std::string::npos) << four.reason;
  // 19 bits: one coordinate per word, so the 6-bank board feeds a second lane at 1/3 rate only.
  EXPECT_EQ(checker.check(config("xc2v6000", 2, 6, 19)).validity, Validity::ok);
  EXPECT_EQ(checker.check(config("xc2v6000", 3, 6, 19)).validity, Validity::too_few_banks);
}

// A device as large as needed: 16 lanes fit, so only the banks decide.
std::string big_device_profile() {
  std::ifstream in(std::string(RC_SOURCE_DIR) + "/configs/devices/virtex4-sx55.json");
  nlohmann::ordered_json j = nlohmann::ordered_json::parse(in);
  j["name"] = "test-big-device";
  j["fpga"]["slices"]["value"] = 1000000;
  j["fpga"]["block_multipliers"]["value"] = 10000;
  const std::string path =
      (std::filesystem::temp_directory_path() / ("rc_sweep_big_device_" + std::to_string(::getpid()) + ".json")).string();
  std::ofstream(path) << j.dump(2);
  return path;
}

TEST(ConfigChecker, SixteenLanesAtFifteenBitsOnSixBanksAreTooFewBanks) {
  const std::string big = big_device_profile();
  const ConfigChecker checker({big, "virtex4-sx55"}, kHost);
  const ConfigCheck c = checker.check(config(big, 16, 6));
  EXPECT_EQ(c.validity, Validity::too_few_banks) << c.reason;
  EXPECT_NE(c.reason.find("16 lanes"), std::string::npos) << c.reason;
  EXPECT_EQ(checker.check(config(big, 16, 26)).validity, Validity::ok);  // 8 groups x 3 + 2: full rate
  EXPECT_EQ(checker.check(config(big, 16, 24)).validity, Validity::ok);  // last group at 1/3 rate
  EXPECT_EQ(checker.check(config(big, 16, 23)).validity, Validity::too_few_banks);
  // On the real Virtex-4 the design itself is too big, and that is what is reported.
  EXPECT_EQ(checker.check(config("virtex4-sx55", 16, 26)).validity, Validity::does_not_fit);
  std::filesystem::remove(big);
}

TEST(ConfigChecker, UnknownProfilesAreBadOptionsNotInvalidConfigurations) {
  EXPECT_THROW(ConfigChecker({"no-such-device"}, kHost), std::invalid_argument);
  EXPECT_THROW(ConfigChecker({"xc2v6000"}, "no-such-host"), std::invalid_argument);
}

TEST(ConfigChecker, CompactBanksHoldTheWholeStepAndEveryFaceWithoutCappingAGroup) {
  const ConfigChecker checker({"xc2v6000"}, kHost);
  const SweepConfig c = config("xc2v6000", 2, 6);
  const std::uint64_t bytes = checker.compact_bank_capacity(c, 1120, 280);
  ASSERT_GT(bytes, 0u);
  EXPECT_LT(bytes, 4u << 20);
  EXPECT_EQ(bytes & (bytes - 1), 0u);  // a power of two
  EXPECT_GE(bytes / 4, 3u * 1120);
  const board::BankLayout small = board::make_bank_layout(c.lanes, c.banks, c.bits, 32, bytes);
  const board::BankLayout full = board::make_bank_layout(c.lanes, c.banks, c.bits, 32, 4u << 20);
  EXPECT_GE(small.max_rays_per_batch, 1120u);
  EXPECT_GE(small.max_faces_per_set, 280u);
  for (std::uint64_t rays : {1u, 37u, 1119u, 1120u}) {
    EXPECT_EQ(board::split_rays(small, rays).rays, board::split_rays(full, rays).rays) << rays;
  }
  // A scene the profile's banks must batch keeps the profile's banks.
  EXPECT_EQ(checker.compact_bank_capacity(c, 1u << 21, 280), 0u);
}

}  // namespace
}  // namespace rc
