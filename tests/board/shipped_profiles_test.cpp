// Every shipped device profile (configs/devices) reads through the profile edge into its typed
// DeviceProfile, and reading it again from the document it keeps gives the same profile: the document
// is the file, and the loader is a function of it alone.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "board/device_profile.h"
#include "profiles/profile_document.h"

namespace rc::board::test {
namespace {

TEST(ShippedProfiles, EveryDeviceRoundTripsThroughTheTypedReader) {
  std::vector<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(profiles::default_config_dir() + "/devices"))
    if (e.path().extension() == ".json") names.push_back(e.path().stem().string());
  std::sort(names.begin(), names.end());
  ASSERT_EQ(names, (std::vector<std::string>{"spartan3-5000", "virtex4-sx55", "xc2v6000"}));
  for (const std::string& name : names) {
    SCOPED_TRACE(name);
    const DeviceProfile p = find_device_profile(name);
    EXPECT_EQ(p.name, name);
    const DeviceProfile again = device_profile_from_document(p.document, p.file);
    EXPECT_TRUE(again.document == p.document);
    EXPECT_EQ(again.part, p.part);
    EXPECT_EQ(again.slices, p.slices);
    EXPECT_EQ(again.block_multipliers, p.block_multipliers);
    EXPECT_EQ(again.block_ram_bits, p.block_ram_bits);
    EXPECT_EQ(again.clock_mhz_by_lanes, p.clock_mhz_by_lanes);
    EXPECT_EQ(again.clock_mhz_default, p.clock_mhz_default);
    EXPECT_EQ(again.bank_count, p.bank_count);
    EXPECT_EQ(again.bank_capacity_bytes, p.bank_capacity_bytes);
    EXPECT_EQ(again.bank_clock_mhz, p.bank_clock_mhz);
    EXPECT_EQ(again.pci_clock_mhz, p.pci_clock_mhz);
    EXPECT_EQ(again.pci_max_burst_bytes, p.pci_max_burst_bytes);
    EXPECT_EQ(again.results, p.results);
    // By name, the process reads the file once; by path, each time, and the two agree.
    const DeviceProfile by_path = find_device_profile(p.file);
    EXPECT_TRUE(by_path.document == p.document);
    EXPECT_EQ(by_path.bank_count, p.bank_count);
  }
}

}  // namespace
}  // namespace rc::board::test
