#include "host_sw/studies/timing_interval.h"

#include <algorithm>
#include <cstdio>
#include <mutex>
#include <stdexcept>

#include "host_sw/studies/paper_prediction.h"
#include "host_sw/studies/paper_workload.h"

namespace rc {

std::pair<double, double> left_out_error_quantiles(const std::vector<CalibratedVariant>& variants, std::size_t* count) {
  std::vector<double> errors;
  for (const CalibratedVariant& v : variants)
    if (v.in_spread) errors.insert(errors.end(), v.left_out_errors.begin(), v.left_out_errors.end());
  if (errors.empty()) throw std::invalid_argument("no calibrated host variant in the spread: no timing interval");
  if (count) *count = errors.size();
  return {quantile(errors, kIntervalQuantiles[0]), quantile(errors, kIntervalQuantiles[1])};
}

namespace {

void check_range(const char* what, std::size_t value, int low, int high, std::vector<std::string>& warnings) {
  if (value >= static_cast<std::size_t>(low) && value <= static_cast<std::size_t>(high)) return;
  warnings.push_back(std::string(what) + " " + std::to_string(value) + " is outside the calibration's range " +
                     std::to_string(low) + ".." + std::to_string(high) +
                     " (Table 2's cells): the timing interval is the calibration's error, not measured here");
}

}  // namespace

TimingInterval timing_interval(double seconds, std::size_t faces, std::size_t patches,
                               const std::vector<CalibratedVariant>& variants, const std::vector<PaperRow>& rows) {
  TimingInterval t;
  t.seconds = seconds;
  const auto [low, high] = left_out_error_quantiles(variants, &t.errors);
  t.error_low = low;
  t.error_high = high;
  const auto bounds = prediction_interval(seconds, seconds, low, high);
  t.low_seconds = bounds.first;
  t.high_seconds = bounds.second;
  if (!rows.empty()) {
    int fmin = rows.front().faces, fmax = fmin, pmin = rows.front().patches, pmax = pmin;
    for (const PaperRow& r : rows) {
      fmin = std::min(fmin, r.faces);
      fmax = std::max(fmax, r.faces);
      pmin = std::min(pmin, r.patches);
      pmax = std::max(pmax, r.patches);
    }
    check_range("faces", faces, fmin, fmax, t.warnings);
    check_range("patches", patches, pmin, pmax, t.warnings);
  }
  return t;
}

TimingInterval timing_interval(double seconds, std::size_t faces, std::size_t patches) {
  static std::mutex guard;
  static std::vector<CalibratedVariant> variants;
  {
    const std::lock_guard<std::mutex> lock(guard);
    if (variants.empty()) variants = load_calibrated_variants(default_variants_path());
  }
  return timing_interval(seconds, faces, patches, variants, default_paper_table());  // read once, by path
}

std::string TimingInterval::text() const {
  char line[256];
  std::snprintf(line, sizeof line, "%.6g s in [%.6g, %.6g] (the calibration's left-out error %+.1f%%..%+.1f%%, %zu left-out errors)",
                seconds, low_seconds, high_seconds, 100.0 * error_low, 100.0 * error_high, errors);
  return line;
}

}  // namespace rc
