#include <gtest/gtest.h>

#include "host_sw/calibration.h"

namespace rc {
namespace {

// Synthetic runs made from known factors on each cost group: the fit recovers the factors and
// leaves no residual; the calibrated profile scales each cost by its group's factor.
TEST(Calibration, RecoversKnownFactorsOnASyntheticCase) {
  const std::array<double, kCostGroups> truth = {2.5, 9.5, 4000, 50, 11};
  std::vector<CalibrationObservation> obs;
  const double shapes[][6] = {
      // software_test, receiver, step, driver_segment, driver_pass, fixed (seconds at factor 1)
      {0.10, 0.02, 1e-4, 0, 0, 0},      {1.5, 0.3, 4e-4, 0, 0, 0},      {30, 1.2, 1.4e-3, 0, 0, 0},
      {500, 1.2, 1.4e-3, 0, 0, 0},      {0, 0.02, 1e-4, 0.001, 0.002, 0.05}, {0, 0.3, 4e-4, 0.02, 0.01, 0.8},
      {0, 1.2, 1.4e-3, 0.9, 0.03, 30},  {0, 1.2, 1.4e-3, 0.9, 0.03, 500}};
  for (const auto& s : shapes) {
    CalibrationObservation o;
    o.label = "synthetic";
    for (int g = 0; g < kCostGroups; ++g) o.group_seconds[g] = s[g];
    o.fixed_seconds = s[5];
    o.measured_seconds = o.fixed_seconds;
    for (int g = 0; g < kCostGroups; ++g) o.measured_seconds += truth[g] * s[g];
    obs.push_back(o);
  }
  const CalibrationFit fit = fit_calibration(obs);
  for (int g = 0; g < kCostGroups; ++g) EXPECT_NEAR(fit.scale[g], truth[g], 1e-6 * truth[g]) << to_string(CostGroup(g));
  EXPECT_LT(fit.rms_relative_residual, 1e-9);

  HostProfile base = find_host_profile("athlon-mp-2600");
  const nlohmann::ordered_json j = calibrated_profile(base, fit, obs, "synthetic-calibrated");
  const double test_estimate = base.json["work_seconds"]["intersection_test"]["value"].get<double>();
  EXPECT_NEAR(j["work_seconds"]["intersection_test"]["value"].get<double>(), truth[0] * test_estimate, 1e-6 * test_estimate);
  EXPECT_NE(j["work_seconds"]["intersection_test"]["source"].get<std::string>().find("fitted"), std::string::npos);
  EXPECT_EQ(j["calibration"]["observations"].size(), obs.size());
}

TEST(Calibration, RejectsObservationsWithoutMeasurements) {
  EXPECT_THROW(fit_calibration({}), std::invalid_argument);
  CalibrationObservation o;
  o.label = "empty";
  EXPECT_THROW(fit_calibration({o}), std::invalid_argument);
}

}  // namespace
}  // namespace rc
