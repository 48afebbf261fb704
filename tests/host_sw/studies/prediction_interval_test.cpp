// Prediction intervals (docs/calibration.md, "Prediction intervals"): quantiles of the calibration's
// left-out errors, the interval's arithmetic, and the variants file's left-out errors as read.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <functional>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "host_sw/studies/calibration_variants.h"
#include "host_sw/studies/paper_prediction.h"

namespace rc {
namespace {

TEST(PredictionInterval, QuantileIsLinearBetweenOrderStatistics) {
  EXPECT_DOUBLE_EQ(quantile({3, 1, 2}, 0.5), 2);
  EXPECT_DOUBLE_EQ(quantile({0, 10}, 0.1), 1);
  EXPECT_DOUBLE_EQ(quantile({0, 10}, 0.9), 9);
  EXPECT_DOUBLE_EQ(quantile({4, 0, 8, 2, 6}, 0.1), 0.8);  // sorted 0 2 4 6 8: 0.4 of the way from 0 to 2
  EXPECT_DOUBLE_EQ(quantile({5}, 0.9), 5);
  EXPECT_THROW((void)quantile({}, 0.5), std::invalid_argument);
}

// A true time t with t (1 + e) = prediction: e = +4% means the model is 4% slow, so t = p / 1.04.
TEST(PredictionInterval, BoundsDivideTheRangeByOnePlusTheErrors) {
  const auto [low, high] = prediction_interval(90, 110, -0.05, 0.04);
  EXPECT_DOUBLE_EQ(low, 90 / 1.04);
  EXPECT_DOUBLE_EQ(high, 110 / 0.95);
  const auto [a, b] = prediction_interval(100, 100, 0, 0);  // no doubt at all: the prediction itself
  EXPECT_EQ(a, 100);
  EXPECT_EQ(b, 100);
  EXPECT_THROW((void)prediction_interval(110, 90, 0, 0), std::invalid_argument);
  EXPECT_THROW((void)prediction_interval(90, 110, 0.1, 0), std::invalid_argument);
  EXPECT_THROW((void)prediction_interval(90, 110, -1, 0), std::invalid_argument);
}

// The shipped variants: each carries its 16 left-out errors, the very numbers of its profile's
// calibration record; an error of -100% or less is refused, naming the variant.
TEST(PredictionInterval, VariantsCarryTheirLeftOutErrors) {
  const std::string shipped = default_variants_path();
  const std::vector<CalibratedVariant> variants = load_calibrated_variants(shipped);
  std::ifstream in(shipped);
  const nlohmann::ordered_json j = nlohmann::ordered_json::parse(in);
  ASSERT_EQ(variants.size(), j["variants"].size());
  for (std::size_t i = 0; i < variants.size(); ++i) {
    const auto& observations = j["variants"][i]["profile"]["calibration"]["observations"];
    ASSERT_EQ(variants[i].left_out_errors.size(), observations.size());
    EXPECT_EQ(variants[i].left_out_errors.size(), 16u);
    for (std::size_t k = 0; k < observations.size(); ++k) {
      EXPECT_EQ(variants[i].left_out_errors[k], observations[k]["left_out_relative_error"].get<double>());
    }
  }
  nlohmann::ordered_json bad = j;
  bad["variants"][0]["profile"]["calibration"]["observations"][3]["left_out_relative_error"] = -1.0;
  const std::string path = ::testing::TempDir() + "variants-bad-error.json";
  std::ofstream(path) << bad.dump();
  try {
    (void)load_calibrated_variants(path);
    FAIL() << "a left-out error of -100% was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("variants[0]: a left_out_relative_error must be finite and above -1"),
              std::string::npos)
        << e.what();
  }
  std::remove(path.c_str());
}

}  // namespace
}  // namespace rc
