#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <string>

#include "host_sw/studies/calibration_json.h"
#include "host_sw/studies/calibration_variants_json.h"
#include "profiles/profile_json.h"

namespace rc {
namespace {

// Synthetic runs made from known factors on each cost group: the fit recovers the factors and
// leaves no residual; the calibrated profile scales each cost by its group's factor.
TEST(Calibration, RecoversKnownFactorsOnASyntheticCase) {
  const std::array<double, kCostGroups> truth = {2.5, 9.5, 4000, 50, 11};
  std::vector<CalibrationObservation> obs;
  const double shapes[][6] = {
      // software_test, receiver, step, driver_data, driver_pass, fixed (seconds at factor 1)
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
  const double test_estimate = profiles::json_of(base.document).at("work_seconds").at("intersection_test").at("value").get<double>();
  EXPECT_NEAR(j["work_seconds"]["intersection_test"]["value"].get<double>(), truth[0] * test_estimate, 1e-6 * test_estimate);
  EXPECT_NE(j["work_seconds"]["intersection_test"]["source"].get<std::string>().find("fitted"), std::string::npos);
  EXPECT_EQ(j["calibration"]["observations"].size(), obs.size());
}

// The per-pass group may not fall below its estimate (factor 1): with data that asks for less, it
// stays at 1 and the others absorb the rest.
TEST(Calibration, PerPassCostsStayAtLeastTheirEstimate) {
  EXPECT_EQ(minimum_scale(CostGroup::DriverPass), 1.0);
  EXPECT_EQ(minimum_scale(CostGroup::Receiver), 0.0);
  std::vector<CalibrationObservation> obs;
  for (double k : {1.0, 2.0, 3.0, 5.0}) {
    CalibrationObservation o;
    o.label = "run";
    o.group_seconds[static_cast<int>(CostGroup::Receiver)] = k;
    o.group_seconds[static_cast<int>(CostGroup::DriverPass)] = 0.1;
    o.measured_seconds = 2 * k;  // explained by the receiver alone: the pass would fit to 0
    obs.push_back(o);
  }
  const CalibrationFit fit = fit_calibration(obs);
  EXPECT_DOUBLE_EQ(fit.scale[static_cast<int>(CostGroup::DriverPass)], 1.0);
  EXPECT_GT(fit.scale[static_cast<int>(CostGroup::Receiver)], 1.9);
}

// Observations made by a known structure, with a little deterministic noise, and a second
// structure that cannot express it: the structure that made the data has the smaller
// leave-one-out error, and is the one best_by_cross_validation picks.
TEST(Calibration, CrossValidationPicksTheStructureThatMadeTheData) {
  // Truth: per-segment driver work plus a per-face-per-pass term (shape C, which "variant A" has
  // and "variant B" lacks: B puts that time nowhere).
  std::vector<CalibrationObservation> a, b;
  const double segments[] = {1, 4, 16, 1, 4, 16, 4, 16, 2, 8};
  const double faces[] = {1, 1, 1, 4, 4, 4, 16, 16, 2, 8};
  for (int i = 0; i < 10; ++i) {
    const double noise = 1 + 0.01 * std::sin(3.7 * i);
    CalibrationObservation o;
    o.label = "run " + std::to_string(i);
    o.group_seconds[static_cast<int>(CostGroup::Receiver)] = segments[i];
    o.group_seconds[static_cast<int>(CostGroup::Step)] = 1;
    o.measured_seconds = (2 * segments[i] + 0.5 + 0.3 * segments[i] * faces[i]) * noise;
    CalibrationObservation with_faces = o, without_faces = o;
    with_faces.group_seconds[static_cast<int>(CostGroup::DriverData)] = segments[i] * faces[i];
    a.push_back(with_faces);
    b.push_back(without_faces);
  }
  const HostProfile base = find_host_profile("athlon-mp-2600");
  std::vector<VariantCalibration> variants = {calibrate_variant(base, b), calibrate_variant(base, a)};
  EXPECT_LT(variants[1].cv.mean_absolute, 0.02);
  EXPECT_GT(variants[0].cv.mean_absolute, 0.1);
  EXPECT_EQ(best_by_cross_validation(variants), 1u);
  EXPECT_FALSE(within_tolerance(variants[0], variants[1]));
  // Leave-one-out by hand for one run: refit without it, predict it.
  std::vector<CalibrationObservation> rest(a.begin() + 1, a.end());
  const CalibrationFit fit = fit_calibration(rest);
  double predicted = a[0].fixed_seconds;
  for (int g = 0; g < kCostGroups; ++g) predicted += fit.scale[g] * a[0].group_seconds[g];
  EXPECT_DOUBLE_EQ(variants[1].cv.relative_errors[0], (predicted - a[0].measured_seconds) / a[0].measured_seconds);
  const nlohmann::ordered_json doc = variants_document(variants, base.name);
  EXPECT_TRUE(doc["variants"][1]["chosen"].get<bool>());
  EXPECT_FALSE(doc["variants"][0]["chosen"].get<bool>());
}

TEST(Calibration, RejectsObservationsWithoutMeasurements) {
  EXPECT_THROW(fit_calibration({}), std::invalid_argument);
  CalibrationObservation o;
  o.label = "empty";
  EXPECT_THROW(fit_calibration({o}), std::invalid_argument);
}

// A fit that does not describe its runs is no profile (issue 27): rms residuals above
// kMaxFitRmsResidual, or a cost group the runs pay fitted to 0 (the non-negativity bound). The
// synthetic fit above passes; measurements 1e8 times the model's (a table in the wrong unit) and
// measurements below the fixed seconds alone (every cost fitted to 0) are refused.
TEST(Calibration, FitsThatDoNotDescribeTheRunsAreRefused) {
  auto observation = [](double software_test, double receiver, double step, double fixed, double measured) {
    CalibrationObservation o;
    o.label = "run";
    o.group_seconds[static_cast<int>(CostGroup::SoftwareTest)] = software_test;
    o.group_seconds[static_cast<int>(CostGroup::Receiver)] = receiver;
    o.group_seconds[static_cast<int>(CostGroup::Step)] = step;
    o.fixed_seconds = fixed;
    o.measured_seconds = measured;
    return o;
  };
  // Made from factors 2, 3, 4 exactly: a fit with no residual and no zero.
  std::vector<CalibrationObservation> good = {observation(1, 0.1, 0.01, 0, 2.34), observation(0.1, 1, 0.01, 0, 3.24),
                                              observation(0.1, 0.1, 1, 0, 4.5), observation(1, 1, 1, 0, 9)};
  EXPECT_EQ(fit_problem(fit_calibration(good), good), "");

  // The fixed seconds alone exceed every measurement: each cost goes to the bound 0.
  std::vector<CalibrationObservation> too_fast = {observation(1, 0.1, 0.01, 5, 1), observation(0.1, 1, 0.01, 5, 2)};
  const CalibrationFit zero = fit_calibration(too_fast);
  EXPECT_EQ(zero.scale[static_cast<int>(CostGroup::SoftwareTest)], 0);
  const std::string rms = fit_problem(zero, too_fast);
  EXPECT_NE(rms.find("the fit misses its 2 runs by"), std::string::npos) << rms;
  EXPECT_NE(rms.find("(at most 25%: kMaxFitRmsResidual"), std::string::npos) << rms;

  // Within the residual bound, but one paid group fitted to 0: the runs were made with an
  // intersection cost of -10 times the estimate, which the fit can only hold at its bound 0.
  std::vector<CalibrationObservation> no_test = {observation(1e-3, 1, 0.01, 0, 3.03), observation(1e-3, 0.1, 1, 0, 4.29),
                                                 observation(1e-3, 1, 1, 0, 6.99)};
  const CalibrationFit fit = fit_calibration(no_test);
  ASSERT_LE(fit.rms_relative_residual, kMaxFitRmsResidual);
  EXPECT_EQ(fit_problem(fit, no_test),
            "the fit sets every cost of group software_test to 0 s (the non-negativity bound), though the runs pay it: "
            "the table's times are shorter than the rest of the model explains");
}

// The variants file `paper --variants` reads: the shipped one loads with one chosen variant in the
// spread; an edited copy with no chosen variant, two, or a chosen one outside the spread is refused.
TEST(Calibration, VariantsFileMustChooseExactlyOneVariantInTheSpread) {
  const std::string shipped = default_variants_path();
  const std::vector<CalibratedVariant> variants = load_calibrated_variants(shipped);
  EXPECT_EQ(std::count_if(variants.begin(), variants.end(), [](const CalibratedVariant& v) { return v.chosen; }), 1);
  std::ifstream in(shipped);
  const nlohmann::ordered_json original = nlohmann::ordered_json::parse(in);
  const std::string path = ::testing::TempDir() + "variants.json";
  auto error_with = [&](const std::function<void(nlohmann::ordered_json&)>& change) {
    nlohmann::ordered_json j = original;
    change(j);
    std::ofstream(path) << j.dump();
    try {
      (void)load_calibrated_variants(path);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what()).substr(path.size());
    }
    return std::string("(no error)");
  };
  EXPECT_EQ(error_with([](nlohmann::ordered_json&) {}), "(no error)");
  EXPECT_EQ(error_with([](nlohmann::ordered_json& j) {
              for (auto& v : j["variants"]) v["chosen"] = false;
            }),
            ": 0 variants are marked \"chosen\"; exactly one must be (rerun `rc2000sim calibrate`)");
  EXPECT_EQ(error_with([](nlohmann::ordered_json& j) {
              for (auto& v : j["variants"]) v["chosen"] = v["in_spread"] = true;
            }),
            ": " + std::to_string(original["variants"].size()) +
                " variants are marked \"chosen\"; exactly one must be (rerun `rc2000sim calibrate`)");
  EXPECT_NE(error_with([](nlohmann::ordered_json& j) {
              for (auto& v : j["variants"]) v["in_spread"] = false;
            }).find("]: the chosen variant must be in the spread"),
            std::string::npos);
  EXPECT_NE(error_with([](nlohmann::ordered_json& j) { j["variants"][0]["cv_mean_absolute_relative_error"] = -3; })
                .find(": variants[0]: cross-validated and fitted errors must be finite and at least 0"),
            std::string::npos);
  std::remove(path.c_str());
}

}  // namespace
}  // namespace rc
