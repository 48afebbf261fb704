// The structural alternatives the paper leaves open about its host driver (DriverModel: cost unit,
// transfer, face upload, overlap), each calibrated on Table 2's given columns and judged by
// leave-one-out cross-validation: the default is the variant that best predicts runs it was not
// fitted to, and the predictions of withheld columns carry the spread of the variants whose
// cross-validated error is within a tolerance of the best (docs/calibration.md, "Variants").
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "host_sw/studies/calibration.h"
#include "host_sw/driver/host_cpu_model.h"

namespace rc {

// Variants within this fraction of the best cross-validated error make the prediction spread.
constexpr double kVariantTolerance = 0.2;

// Every combination a serial run can tell apart (cost unit x transfer x face upload), with
// `base`'s overlap and PIO round trip. The overlap only matters to the concurrent driver: every
// serial variant's fit holds for both overlaps.
std::vector<DriverModel> serial_driver_variants(const DriverModel& base);
// `model` with each overlap the concurrent driver may use.
std::vector<DriverModel> with_each_overlap(const DriverModel& model);

struct VariantCalibration {
  HostProfile used;  // the profile the observations were simulated with
  std::vector<CalibrationObservation> observations;
  CalibrationFit fit;
  CrossValidation cv;
};

// Fits and cross-validates one variant's observations.
VariantCalibration calibrate_variant(const HostProfile& used, std::vector<CalibrationObservation> observations);

// The variant with the least cross-validated mean absolute error (the first on a tie).
std::size_t best_by_cross_validation(const std::vector<VariantCalibration>& variants);
bool within_tolerance(const VariantCalibration& variant, const VariantCalibration& best);

// One calibrated variant as `paper` uses it.
struct CalibratedVariant {
  HostProfile profile;       // calibrated; its driver model is the variant
  double cv_error = 0;       // cross-validated mean absolute relative error
  double fit_rms = 0;        // rms relative residual of the fit to all the runs
  bool chosen = false;       // the default (least CV error)
  bool in_spread = false;    // within kVariantTolerance of the chosen one
  // Each calibration run's left-out relative error, (prediction - measured) / measured, from the
  // profile's calibration record (the prediction intervals' calibration part).
  std::vector<double> left_out_errors;
};

// The variants file (schema rc2000sim.host-variants/1, written by calibration_variants_json.h) read
// back through the profile edge (profiles/variants_file.h); throws std::invalid_argument naming
// the file and the problem.
std::vector<CalibratedVariant> load_calibrated_variants(const std::string& path);
std::string default_variants_path();  // configs/calibration/athlon-mp-2600-variants.json

}  // namespace rc
