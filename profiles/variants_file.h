// The calibrated driver-model variants file (configs/calibration/*-variants.json, schema
// rc2000sim.host-variants/1, written by `rc2000sim calibrate`) read at the profile edge: each
// variant's figures as typed values and its calibrated host profile as a document, for the host
// profile's own loader (host_sw/studies/calibration_variants.h checks that they say one coherent thing).
#pragma once

#include <string>
#include <vector>

#include "profiles/profile_document.h"

namespace rc::profiles {

struct VariantRecord {
  std::string driver_model;  // DriverModel::name(), "per_word/pio/every_pass/form_factors"
  ProfileDocument profile;   // the calibrated host profile
  double cv_error = 0;       // cv_mean_absolute_relative_error
  double fit_rms = 0;        // fit_rms_relative_residual
  bool chosen = false;
  bool in_spread = false;
  // Each observation's leave-one-out relative error (profile.calibration.observations[].left_out_relative_error):
  // the calibration's own uncertainty behind the paper's prediction intervals.
  std::vector<double> left_out_errors;
};

// Throws std::invalid_argument naming the file and the problem (a missing key, a wrong type, a schema
// other than rc2000sim.host-variants/1).
std::vector<VariantRecord> read_variants_file(const std::string& path);

}  // namespace rc::profiles
