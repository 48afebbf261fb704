#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "host_sw/studies/config_checker.h"
#include "host_sw/studies/sweep_csv.h"
#include "host_sw/studies/sweep_row_json.h"
#include "tests/host_sw/studies/sweep_test_support.h"

namespace rc {
namespace {

using namespace sweep_test;

TEST(SweepCsv, SpeedupsAndCsvAreStable) {
  const ConfigChecker checker({"xc2v6000"}, kHost);
  std::vector<SweepRow> rows;
  rows.push_back(row_from_report(config("xc2v6000", 1, 6), synthetic_report(6.0, 2.0), 10));
  rows.push_back(row_from_report(config("xc2v6000", 2, 6), synthetic_report(3.0, 2.0), 10));
  rows.push_back(row_from_report(config("xc2v6000", 2, 7), synthetic_report(3.0, 2.0), 10));  // no 1-lane row at 7 banks
  rows.push_back(invalid_row(config("xc2v6000", 12, 6), checker.check(config("xc2v6000", 12, 6)), 10));
  fill_speedups(rows, {{software_key(rows[0].config), 19.0}});
  EXPECT_DOUBLE_EQ(rows[0].speedup_vs_one_lane, 1.0);
  EXPECT_DOUBLE_EQ(rows[1].speedup_vs_one_lane, 9.5 / 6.5);
  EXPECT_TRUE(std::isnan(rows[2].speedup_vs_one_lane));
  EXPECT_DOUBLE_EQ(rows[1].speedup_vs_software, 19.0 / 6.5);
  EXPECT_TRUE(std::isnan(rows[3].speedup_vs_software));

  std::ostringstream csv;
  write_sweep_csv(csv, rows);
  std::istringstream lines(csv.str());
  std::string header, first, second, third, invalid;
  std::getline(lines, header);
  std::getline(lines, first);
  std::getline(lines, second);
  std::getline(lines, third);
  std::getline(lines, invalid);
  EXPECT_EQ(header,
            "device,lanes,banks,bits,concurrent,status,invalid_kind,reason,steps,clock_mhz,nominal_rays_per_cycle,"
            "simulated_seconds,fpga_busy_seconds,host_compute_seconds,driver_cpu_seconds,pci_transfer_seconds,"
            "waiting_seconds,pci_utilisation,max_bank_utilisation,busiest_bank,busiest_bank_role,"
            "mean_lane_utilisation,intersections_per_second_while_busy,fpga_limit,fpga_limit_share,bottleneck,"
            "speedup_vs_one_lane,speedup_vs_software,energy_joules,energy_per_step_joules,"
            "energy_per_intersection_nanojoules,average_watts,energy_delay_product_joule_seconds,fpga_joules,"
            "sram_joules,pci_joules,host_joules,energy_missing,pareto_time_energy,stream_bound,"
            "stream_bound_tests_per_second,stream_next,stream_next_tests_per_second,run_bound,run_next,"
            "lane_tests_per_second_peak,sram_bytes_per_second,sram_bytes_per_test,busiest_bank_bytes_per_second,"
            "pci_bytes_per_second_to_board,pci_bytes_per_second_to_host,pci_mode");
  EXPECT_EQ(second.rfind("xc2v6000,2,6,15,1,ok,,,10,52.5,2,6.5,4,2,1,0.5,3,", 0), 0u) << second;
  // The reason holds commas, so it is quoted; the numbers of an invalid row are empty.
  EXPECT_EQ(invalid.rfind("xc2v6000,12,6,15,1,invalid,does_not_fit,\"12 lane(s)", 0), 0u) << invalid;
  EXPECT_NE(invalid.find(",,,,,,,,,,,"), std::string::npos) << invalid;
  const nlohmann::ordered_json j = sweep_row_json(rows[3]);
  EXPECT_EQ(j["status"], "invalid");
  EXPECT_TRUE(j["simulated_seconds"].is_null());
  EXPECT_EQ(j["concurrent"], true);
}

}  // namespace
}  // namespace rc
