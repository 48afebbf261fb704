// Device and host profiles, the bank layout's capacities, and every configuration error: each
// must fail with a message that says what is wrong.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "board/bank_layout.h"
#include "board/board_params.h"
#include "board/device_profile.h"
#include "host_sw/platform/board_run.h"
#include "tests/host_sw/platform/system_support.h"
#include "profiles/profile_json.h"

namespace rc::board {
namespace {

// Runs `f`, expecting std::invalid_argument whose message contains every one of `parts`.
template <class F>
void expect_error(F f, std::initializer_list<const char*> parts) {
  try {
    f();
    ADD_FAILURE() << "no exception";
  } catch (const std::invalid_argument& e) {
    for (const char* p : parts) EXPECT_NE(std::string(e.what()).find(p), std::string::npos) << e.what() << " lacks " << p;
  }
}

TEST(DeviceProfiles, ShippedProfilesLoadWithThePapersNumbers) {
  const DeviceProfile v2 = find_device_profile("xc2v6000");
  EXPECT_EQ(v2.part, "XC2V6000");
  EXPECT_EQ(v2.clock_mhz(1), 53.833);
  EXPECT_EQ(v2.clock_mhz(2), 52.5);
  EXPECT_EQ(v2.bank_count, 6u);
  EXPECT_EQ(v2.bank_capacity_bytes, 4u << 20);
  EXPECT_EQ(v2.pipeline_latency_cycles, 37u);
  BoardChoices one;
  EXPECT_EQ(make_board_params(v2, one).timing.device_period, sc_core::sc_time(18576, sc_core::SC_PS));  // 53.833 MHz
  one.lanes = 2;
  EXPECT_EQ(make_board_params(v2, one).timing.device_period, sc_core::sc_time(19048, sc_core::SC_PS));  // 52.5 MHz
  for (const char* name : {"virtex4-sx55", "spartan3-5000"}) {
    const DeviceProfile p = find_device_profile(name);
    EXPECT_EQ(p.clock_mhz(1), 176.9) << name;
    EXPECT_EQ(p.clock_mhz(9), 176.9) << name;
    EXPECT_EQ(p.bank_clock_mhz, 100.0) << name;
  }
  EXPECT_EQ(rc::profiles::json_of(find_device_profile("virtex4-sx55").document)["fpga"]["block_multipliers"]["value"], 512);
  EXPECT_EQ(rc::profiles::json_of(find_device_profile("spartan3-5000").document)["fpga"]["slices"]["value"], 33280);
  const HostProfile host = find_host_profile("athlon-mp-2600");
  EXPECT_EQ(host.clock_hz, 2133e6);
  EXPECT_GT(host.work[static_cast<int>(HostWork::FormFactor)], sc_core::SC_ZERO_TIME);
}

// Paper sec 4.4: 4MB banks hold 2^20 rays and about 116,000 faces (4 MiB / 36 B).
TEST(BankLayouts, CapacitiesFollowFromBankSizes) {
  const BankLayout one = make_bank_layout(1, 6, 15, 32, 4u << 20);
  EXPECT_EQ(one.max_rays_per_batch, 1u << 20);
  EXPECT_EQ(one.max_faces_per_set, (4u << 20) / 36);
  EXPECT_EQ(one.mask_bank, 5u);
  EXPECT_EQ(one.role(1), "rays g0 X");
  const BankLayout two = make_bank_layout(2, 6, 15, 32, 4u << 20);
  EXPECT_EQ(two.coords_per_word, 2u);
  EXPECT_EQ(two.field_bits, 16u);
  EXPECT_EQ(two.max_rays_per_batch, 1u << 21);
  // Three lanes at 15 bits on six banks: a second group in one bank; no spare bank is left, so the
  // own-face table follows the face records (4 MiB / 40 B faces).
  const BankLayout three = make_bank_layout(3, 6, 15, 32, 4u << 20);
  ASSERT_EQ(three.groups.size(), 2u);
  EXPECT_EQ(three.groups[1].k(), 1u);
  EXPECT_FALSE(three.mask_bank.has_value());
  EXPECT_EQ(three.max_faces_per_set, (4u << 20) / 40);
  EXPECT_DOUBLE_EQ(three.nominal_rays_per_cycle(), 2 + 1.0 / 3);
  // Eight lanes of 7-bit coordinates (four per word) in 3N+2 = 8 banks.
  const BankLayout eight = make_bank_layout(8, 8, 7, 32, 4u << 20);
  EXPECT_EQ(eight.groups.size(), 2u);
  EXPECT_EQ(eight.banks_used(), 8u);
}

TEST(BankLayouts, BadConfigurationsFailClearly) {
  expect_error([] { make_bank_layout(1, 0, 15, 32, 1 << 20); }, {"at least 5 banks", "has 0"});
  expect_error([] { make_bank_layout(1, 4, 15, 32, 1 << 20); }, {"at least 5 banks", "has 4"});
  expect_error([] { make_bank_layout(0, 6, 15, 32, 1 << 20); }, {"lane count 0", "at least 1"});
  expect_error([] { make_bank_layout(3, 6, 31, 32, 1 << 20); }, {"3 lanes", "need 11 banks", "at least 9", "has 6"});
  expect_error([] { make_bank_layout(5, 6, 15, 32, 1 << 20); }, {"5 lanes", "need 11 banks", "has 6"});
  expect_error([] { make_bank_layout(1, 6, 40, 32, 1 << 20); }, {"40", "out of range"});
  expect_error([] { make_bank_layout(1, 6, 6, 32, 1 << 20); }, {"6", "out of range"});
  BoardRunOptions o;
  o.device = "no-such-board";
  expect_error([&] { make_board_setup(o); }, {"no devices profile 'no-such-board'"});
  o.device = "xc2v6000";
  o.lanes = 5;
  o.bits = 15;
  expect_error([&] { make_board_setup(o); }, {"5 lanes", "has 6"});
  // Lanes that do not fit the device's slices and block multipliers.
  o.lanes = 3;
  o.bits = 31;
  expect_error([&] { make_board_setup(o); }, {"3 lane(s) at 31 bits on xc2v6000", "39307 slices", "does not fit"});
  // A lane count is checked where it is made (board/lane_count.h).
  expect_error([&] { o.lanes = 0; }, {"lane count 0", "at least 1 and at most 255"});
  expect_error([&] { o.lanes = 256; }, {"lane count 256", "at least 1 and at most 255", "CONFIG register"});
  EXPECT_EQ(o.lanes, 3u);
}

TEST(DeviceProfiles, BrokenProfilesNameFileAndField) {
  const std::string path = (std::filesystem::temp_directory_path() / ("rc_profile_" + std::to_string(getpid()) + ".json")).string();
  nlohmann::ordered_json good = rc::profiles::json_of(find_device_profile("xc2v6000").document);
  auto check = [&](nlohmann::ordered_json j, std::initializer_list<const char*> parts) {
    std::ofstream(path) << j.dump();
    expect_error([&] { load_device_profile(path); }, parts);
  };
  nlohmann::ordered_json j = good;
  j["banks"].erase("clock_mhz");
  check(j, {path.c_str(), "banks.clock_mhz: missing"});
  j = good;
  j["banks"]["count"] = 6;
  check(j, {"banks.count", "source"});
  j = good;
  j["banks"]["count"]["source"] = "";
  check(j, {"banks.count", "source"});
  j = good;
  j["banks"]["word_bits"]["value"] = 48;
  check(j, {"banks.word_bits", "32 or 64"});
  j = good;
  j["pci"]["burst_efficiency"]["value"] = 1.5;
  check(j, {"pci.burst_efficiency", "outside"});
  j = good;
  j["clock"].erase("mhz_default");
  std::ofstream(path) << j.dump();
  expect_error([&] { load_device_profile(path).clock_mhz(3); }, {"no clock for 3 lanes"});
  std::ofstream(path) << "{ not json";
  expect_error([&] { load_device_profile(path); }, {"not valid JSON"});
  std::filesystem::remove(path);
}

// A scene beyond one face set or one ray batch, with batching forbidden: the host thread's error
// comes out of the simulation with the limits in its message.
TEST(BoardSystemErrors, SceneBeyondCapacityWithoutBatching) {
  SceneOptions so;
  so.face_target = 70;
  so.patch_levels = 3;  // 4480 patches: thousands of segments per step
  const Scene scene = prepare_scene(so).scene;
  BoardRunOptions o;
  o.allow_batching = false;
  o.bank_capacity_bytes = 1024;    // 256 words: 28 faces per set
  BoardSystem faces("faces", scene, test::steps(2), test::setup(o));
  o.bank_capacity_bytes = 70 * 36; // 630 words: all 70 faces, but only 630 rays per batch
  BoardSystem rays("rays", scene, test::steps(2), test::setup(o));
  sc_core::sc_start();
  ASSERT_TRUE(faces.finished() && rays.finished());
  expect_error([&] { faces.rethrow_if_failed(); }, {"70 faces", "one face set holds 28", "allow batching"});
  expect_error([&] { rays.rethrow_if_failed(); }, {"segments but one batch holds 630", "allow batching"});
}

}  // namespace
}  // namespace rc::board
