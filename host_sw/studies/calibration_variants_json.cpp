#include "host_sw/studies/calibration_variants_json.h"

#include "host_sw/studies/calibration_json.h"

namespace rc {

nlohmann::ordered_json variants_document(const std::vector<VariantCalibration>& variants, const std::string& base_name) {
  const std::size_t best = best_by_cross_validation(variants);
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < variants.size(); ++i) {
    const VariantCalibration& v = variants[i];
    list.push_back({{"driver_model", v.used.driver_model.name()},
                    {"chosen", i == best},
                    {"in_spread", within_tolerance(v, variants[best])},
                    {"fit_rms_relative_residual", v.fit.rms_relative_residual},
                    {"cv_mean_absolute_relative_error", v.cv.mean_absolute},
                    {"cv_rms_relative_error", v.cv.rms},
                    {"cv_worst_relative_error", v.cv.worst},
                    {"profile", calibrated_profile(v.used, v.fit, v.observations, base_name + "-calibrated", &v.cv)}});
  }
  return {{"schema", "rc2000sim.host-variants/1"},
          {"description", "Every driver-model variant of " + base_name +
                              ".json calibrated on Table 2's software and single-pipeline columns, with its "
                              "leave-one-out cross-validated error. Written by `rc2000sim calibrate`; read by "
                              "`rc2000sim paper` for the prediction spread (docs/calibration.md, Variants)."},
          {"choice", "least cross-validated mean absolute relative error"},
          {"spread_tolerance", kVariantTolerance},
          {"variants", list}};
}

}  // namespace rc
