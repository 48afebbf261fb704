// The roofs of a board, worked by hand on the RC2000 profile, and the CSV the plot reads.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "host_sw/studies/roofline.h"

namespace rc::test {
namespace {

TEST(Roofline, RoofsOfTheRc2000ByHand) {
  const board::DeviceProfile rc2000 = board::find_device_profile("xc2v6000");
  Roofline r = device_roofs(rc2000, 2, 52.5, 6, 100);
  EXPECT_DOUBLE_EQ(r.lanes_tests_per_second, 2 * 52.5e6);         // lanes x clock
  EXPECT_DOUBLE_EQ(r.sram_bytes_per_second, 6 * 4 * 100e6);       // sec 5.6(a)'s 2.4 GB/s
  EXPECT_DOUBLE_EQ(r.pci_bytes_per_second, 8 * 66.667e6 * 1.0);   // 64-bit, 66.667 MHz, burst efficiency 1
  // Below 2.4e9 / 1.05e8 = 22.9 bytes per test the lanes bound, above it the banks.
  EXPECT_DOUBLE_EQ(r.attainable(6.125), 2 * 52.5e6);
  EXPECT_DOUBLE_EQ(r.attainable(40), 2.4e9 / 40);
  // Flat roofs of a workload: 1 PCI byte per test allows the PCI bandwidth in tests/s; a host that
  // needs 2 s for 1e8 tests keeps up with 5e7 per second, below every other roof.
  workload_roofs(r, 1.0, 2.0, 1e8);
  EXPECT_DOUBLE_EQ(r.pci_tests_per_second, 8 * 66.667e6);
  EXPECT_DOUBLE_EQ(r.host_tests_per_second, 5e7);
  EXPECT_DOUBLE_EQ(r.attainable(6.125), 5e7);
}

TEST(Roofline, CsvHasOneRowPerRoofAndPoint) {
  const board::DeviceProfile rc2000 = board::find_device_profile("xc2v6000");
  Roofline r = device_roofs(rc2000, 2, 52.5, 6, 100);
  r.points.push_back({"paper", "a \"quoted\" label, with a comma", 6.125, 1.04e8});
  std::istringstream csv(roofline_csv({r}));
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line, "kind,device,label,bytes_per_test,tests_per_second");
  int rows = 0;
  std::string last;
  while (std::getline(csv, line)) ++rows, last = line;
  EXPECT_EQ(rows, 3);  // lanes, SRAM (no PCI or host roof without a workload), the point
  EXPECT_EQ(last, "paper,xc2v6000,\"a \"\"quoted\"\" label, with a comma\",6.125,104000000");
}

}  // namespace
}  // namespace rc::test
