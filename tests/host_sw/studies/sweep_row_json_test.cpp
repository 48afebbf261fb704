#include <gtest/gtest.h>

#include "host_sw/studies/config_checker.h"
#include "host_sw/studies/sweep_pareto.h"
#include "host_sw/studies/sweep_row_json.h"
#include "tests/host_sw/studies/sweep_test_support.h"

namespace rc {
namespace {

using namespace sweep_test;

// A row read back from a shard must hold figures a run can produce (issue 27: merge accepted
// negative and 1e308 simulated seconds): each edit below is refused naming the row and the key; the
// row as written, and an invalid row's nulls, pass.
TEST(SweepRowJson, RowsReadBackMustHoldFiguresARunProduces) {
  const SweepRow r = row_from_report(config("xc2v6000", 2, 6), report_with_energy(3.0, 100.0), 10);
  const nlohmann::ordered_json good = sweep_row_json(r);
  EXPECT_NO_THROW((void)sweep_row_from_json(good, r.config));
  auto error_with = [&](const char* key, const nlohmann::ordered_json& value) {
    nlohmann::ordered_json j = good;
    j[key] = value;
    try {
      (void)sweep_row_from_json(j, r.config);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("(accepted)");
  };
  const std::string row = "row " + r.config.label() + ": ";
  EXPECT_EQ(error_with("simulated_seconds", -1.0),
            row + "simulated_seconds = -1.0 is not a figure a run produces (a finite number, not negative, or null)");
  EXPECT_EQ(error_with("simulated_seconds", 1e308),
            row + "simulated_seconds = 1e+308 is outside (0, 1e+12] for a simulated row (kMaxRowSeconds)");
  EXPECT_EQ(error_with("simulated_seconds", 0.0),
            row + "simulated_seconds = 0 is outside (0, 1e+12] for a simulated row (kMaxRowSeconds)");
  EXPECT_EQ(error_with("simulated_seconds", nullptr),
            row + "simulated_seconds = nan is outside (0, 1e+12] for a simulated row (kMaxRowSeconds)");
  EXPECT_EQ(error_with("energy_joules", -100.0),
            row + "energy_joules = -100.0 is not a figure a run produces (a finite number, not negative, or null)");
  EXPECT_EQ(error_with("waiting_seconds", "3"),
            row + "waiting_seconds = \"3\" is not a figure a run produces (a finite number, not negative, or null)");
  EXPECT_EQ(error_with("mean_lane_utilisation", 1.5), row + "mean_lane_utilisation = 1.5 is above 1 (a share)");
  EXPECT_EQ(error_with("energy_joules", nullptr), "(accepted)");  // energy not estimated
  // The busiest bank over the FPGA's busy time may pass 1 (the host's DMA while the FPGA is idle;
  // a one-lane Virtex-4 sweep failed on 1.0005), but not the whole run over the FPGA's busy time.
  const double most = r.simulated_seconds / r.fpga_busy_seconds;
  EXPECT_EQ(error_with("max_bank_utilisation", 1.0005 < most ? 1.0005 : most), "(accepted)");
  EXPECT_NE(error_with("max_bank_utilisation", most * 1.01).find("max_bank_utilisation = "), std::string::npos);

  const ConfigChecker checker({"xc2v6000"}, kHost);
  const SweepRow invalid = invalid_row(config("xc2v6000", 12, 6), checker.check(config("xc2v6000", 12, 6)), 10);
  EXPECT_NO_THROW((void)sweep_row_from_json(sweep_row_json(invalid), invalid.config));
}

// A row without energy writes nulls (not "off the front": there is no energy to compare), and the
// shard round trip keeps every energy column.
TEST(SweepRowJson, EnergyColumnsRoundTripAndAreNullWithoutEnergy) {
  const SweepRow r = row_from_report(config("xc2v6000", 2, 6), report_with_energy(3.0, 100.0), 10);
  RunReport without = synthetic_report(3.0, 2.0);
  without.energy_missing = "device profile x.json has no energy table";
  const SweepRow m = row_from_report(config("xc2v6000", 2, 6), without, 10);
  const nlohmann::ordered_json j = sweep_row_json(m);
  EXPECT_TRUE(j["energy_joules"].is_null());
  EXPECT_TRUE(j["pareto_time_energy"].is_null());  // not "off the front": there is no energy to compare

  std::vector<SweepRow> rows = {r};
  mark_pareto_time_energy(rows);
  const SweepRow back = sweep_row_from_json(sweep_row_json(rows[0]), rows[0].config);
  EXPECT_DOUBLE_EQ(back.energy_joules, 100.0);
  EXPECT_DOUBLE_EQ(back.energy_per_intersection_nanojoules, 100.0);
  EXPECT_DOUBLE_EQ(back.host_joules, 94.0);
  EXPECT_TRUE(back.pareto_time_energy);
  // and every bound column.
  EXPECT_EQ(back.stream_bound, r.stream_bound);
  EXPECT_EQ(back.stream_next, r.stream_next);
  EXPECT_EQ(back.run_bound, r.run_bound);
  EXPECT_EQ(back.run_next, r.run_next);
  EXPECT_EQ(back.pci_mode, r.pci_mode);
  EXPECT_DOUBLE_EQ(back.lane_tests_per_second_peak, r.lane_tests_per_second_peak);
  EXPECT_DOUBLE_EQ(back.sram_bytes_per_test, r.sram_bytes_per_test);
}

}  // namespace
}  // namespace rc
