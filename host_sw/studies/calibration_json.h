// The output edge of a calibration (host_sw/studies/calibration.h): the calibrated host profile as
// `rc2000sim calibrate` writes it, the base profile's document with each cost scaled and sourced.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "host_sw/studies/calibration.h"

namespace rc {

// The profile with every cost scaled by its group's factor, each value's source saying so, and
// the fit (method, observations, residuals, and the cross-validation if given) recorded beside it.
// `base` is the profile the observations were simulated with, driver model included.
nlohmann::ordered_json calibrated_profile(const HostProfile& base, const CalibrationFit& fit,
                                          const std::vector<CalibrationObservation>& observations,
                                          const std::string& name, const CrossValidation* cv = nullptr);

}  // namespace rc
