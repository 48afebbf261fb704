// The uncertainty of a simulated time where users decide (issue 39): the interval `paper` gives its
// predictions (docs/calibration.md, "Prediction intervals"), for one simulated time: the calibration's
// left-out relative errors e (pooled over the in-spread host variants) bound the true time at
// seconds / (1 + e), between the 10% and 90% quantiles; and the workload checked against what the
// calibration saw (Table 2's 16 cells: faces and patches), a warning naming each quantity outside.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "host_sw/studies/calibration_variants.h"
#include "host_sw/studies/paper_workload.h"

namespace rc {

struct TimingInterval {
  double seconds = 0, low_seconds = 0, high_seconds = 0;
  double error_low = 0, error_high = 0;  // the left-out error quantiles (kIntervalQuantiles)
  std::size_t errors = 0;                // left-out errors pooled
  std::vector<std::string> warnings;     // a workload quantity outside the calibration's range
  std::string text() const;              // "78.4 s in [74.2, 81.6] (calibration's left-out error -3.9%..+3.9%)"
};

// The left-out error quantiles of `variants` (in-spread ones pooled), as predict_paper takes them.
std::pair<double, double> left_out_error_quantiles(const std::vector<CalibratedVariant>& variants, std::size_t* count);

// The interval of `seconds` and the range warnings for a workload of `faces` faces and `patches`
// patches, against the calibration cells `rows` (Table 2's). Throws std::invalid_argument when no
// variant is in the spread.
TimingInterval timing_interval(double seconds, std::size_t faces, std::size_t patches,
                               const std::vector<CalibratedVariant>& variants, const std::vector<PaperRow>& rows);

// The same from the shipped files (default_variants_path, default_paper_table_path), read once.
TimingInterval timing_interval(double seconds, std::size_t faces, std::size_t patches);

}  // namespace rc
