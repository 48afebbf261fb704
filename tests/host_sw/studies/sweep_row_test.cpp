#include <gtest/gtest.h>

#include <cmath>

#include "host_sw/studies/sweep_row.h"
#include "tests/host_sw/studies/sweep_test_support.h"

namespace rc {
namespace {

using namespace sweep_test;

TEST(SweepRow, RowsComeFromTheReportAndNameTheBottleneck) {
  const SweepRow r = row_from_report(config("xc2v6000", 2, 6), synthetic_report(3.0, 2.0), 385);
  EXPECT_EQ(r.validity, Validity::ok);
  EXPECT_EQ(r.steps, 385);
  EXPECT_DOUBLE_EQ(r.clock_mhz, 52.5);
  EXPECT_DOUBLE_EQ(r.simulated_seconds, 6.5);
  EXPECT_DOUBLE_EQ(r.pci_utilisation, 0.25 / 6.5);
  EXPECT_EQ(r.busiest_bank, 4);
  EXPECT_EQ(r.busiest_bank_role, "results");
  EXPECT_DOUBLE_EQ(r.max_bank_utilisation, 0.75);
  EXPECT_DOUBLE_EQ(r.mean_lane_utilisation, 0.85);
  EXPECT_EQ(r.fpga_limit, "bank 4 (results)");
  EXPECT_DOUBLE_EQ(r.fpga_limit_share, 0.75);
  EXPECT_EQ(r.bottleneck, "fpga_result_bank");  // waiting is the largest part of the host's timeline
  EXPECT_EQ(row_from_report(config("xc2v6000", 2, 6), synthetic_report(1.0, 2.0), 385).bottleneck, "host_compute");

  // The bound model's columns (host_sw/platform/run_bounds.h, tested there): the same stream bound,
  // the host timeline's parts in order, the lanes' peak and the PCI's mode.
  EXPECT_EQ(r.stream_bound, "bank 4 (results, written)");  // the report's groups share no word
  EXPECT_EQ(r.run_bound, "fpga");
  EXPECT_EQ(r.run_next, "host_compute");
  EXPECT_DOUBLE_EQ(r.lane_tests_per_second_peak, 2 * 52.5e6);
  EXPECT_EQ(r.pci_mode, "DMA");
  EXPECT_DOUBLE_EQ(r.busiest_bank_bytes_per_second, 0.0);  // the report moved no bytes

  EXPECT_EQ(fpga_limit_kind("lanes"), "fpga_lanes");
  EXPECT_EQ(fpga_limit_kind("bank 7 (results)"), "fpga_result_bank");
  EXPECT_EQ(fpga_limit_kind("bank 2 (rays g0 Y)"), "fpga_ray_bank");
  EXPECT_EQ(fpga_limit_kind("bank 4 (rays g1 XYZ)"), "fpga_ray_bank");
  EXPECT_EQ(fpga_limit_kind(""), "fpga_other");
}

TEST(SweepRow, EnergyColumnsComeFromTheReportOrSayWhyNot) {
  const SweepRow r = row_from_report(config("xc2v6000", 2, 6), report_with_energy(3.0, 100.0), 10);
  EXPECT_DOUBLE_EQ(r.energy_joules, 100.0);
  EXPECT_DOUBLE_EQ(r.energy_per_step_joules, 10.0);
  EXPECT_DOUBLE_EQ(r.energy_per_intersection_nanojoules, 100.0);
  EXPECT_DOUBLE_EQ(r.average_watts, 100.0 / 6.5);
  EXPECT_DOUBLE_EQ(r.energy_delay_product_joule_seconds, 650.0);
  EXPECT_DOUBLE_EQ(r.fpga_joules, 1.0);
  EXPECT_DOUBLE_EQ(r.sram_joules, 2.0);
  EXPECT_DOUBLE_EQ(r.pci_joules, 3.0);
  EXPECT_DOUBLE_EQ(r.host_joules, 94.0);
  EXPECT_EQ(r.energy_missing, "");

  RunReport without = synthetic_report(3.0, 2.0);
  without.energy_missing = "device profile x.json has no energy table";
  const SweepRow m = row_from_report(config("xc2v6000", 2, 6), without, 10);
  EXPECT_TRUE(std::isnan(m.energy_joules));
  EXPECT_TRUE(std::isnan(m.host_joules));
  EXPECT_EQ(m.energy_missing, "device profile x.json has no energy table");
}

}  // namespace
}  // namespace rc
