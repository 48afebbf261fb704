// The output edge of the driver-model variants (host_sw/studies/calibration_variants.h): the
// variants file `rc2000sim calibrate` writes and `rc2000sim paper` reads back
// (profiles/variants_file.h).
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "host_sw/studies/calibration_variants.h"

namespace rc {

// The variants file (schema rc2000sim.host-variants/1): every variant's calibrated profile, its fit
// and cross-validation, which one is the default and which make the spread.
nlohmann::ordered_json variants_document(const std::vector<VariantCalibration>& variants, const std::string& base_name);

}  // namespace rc
