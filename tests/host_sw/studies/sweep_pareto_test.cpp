#include <gtest/gtest.h>

#include "host_sw/studies/sweep_pareto.h"
#include "tests/host_sw/studies/sweep_test_support.h"

namespace rc {
namespace {

using namespace sweep_test;

// Time against energy: a row is on the front unless another of the same width and profile settings
// is no slower, no costlier and better in one. Rows without energy are never on it.
TEST(SweepPareto, ParetoFrontOfTimeAgainstEnergy) {
  std::vector<SweepRow> rows;
  rows.push_back(row_from_report(config("xc2v6000", 1, 6), report_with_energy(6.0, 100.0), 10));  // slow, frugal
  rows.push_back(row_from_report(config("xc2v6000", 2, 6), report_with_energy(3.0, 120.0), 10));  // fast, costly
  rows.push_back(row_from_report(config("xc2v6000", 2, 7), report_with_energy(3.0, 130.0), 10));  // as fast, costlier
  rows.push_back(row_from_report(config("xc2v6000", 4, 6), report_with_energy(3.0, 120.0), 10));  // a tie: both stay
  RunReport none = synthetic_report(1.0, 2.0);  // the fastest, but without energy
  none.energy_missing = "no table";
  rows.push_back(row_from_report(config("xc2v6000", 4, 7), none, 10));
  SweepConfig other_width = config("xc2v6000", 1, 7);
  other_width.bits = 23;  // its own front, however costly
  rows.push_back(row_from_report(other_width, report_with_energy(9.0, 500.0), 10));
  mark_pareto_time_energy(rows);
  EXPECT_TRUE(rows[0].pareto_time_energy);
  EXPECT_TRUE(rows[1].pareto_time_energy);
  EXPECT_FALSE(rows[2].pareto_time_energy);
  EXPECT_TRUE(rows[3].pareto_time_energy);
  EXPECT_FALSE(rows[4].pareto_time_energy);
  EXPECT_TRUE(rows[5].pareto_time_energy);
}

}  // namespace
}  // namespace rc
