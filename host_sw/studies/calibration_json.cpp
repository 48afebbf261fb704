#include "host_sw/studies/calibration_json.h"

#include <cstdio>

#include "profiles/profile_json.h"

namespace rc {

namespace {

// The driver kinds a cost unit charges; the others keep their estimate, marked unused.
bool used_by(DriverWork w, DriverModel::CostUnit unit) {
  switch (w) {
    case DriverWork::Call: return true;
    case DriverWork::SegmentPack:
    case DriverWork::ResultUnpack:
    case DriverWork::FacePack: return unit == DriverModel::CostUnit::PerSegment;
    default: return unit == DriverModel::CostUnit::PerWord;
  }
}

}  // namespace

nlohmann::ordered_json calibrated_profile(const HostProfile& base, const CalibrationFit& fit,
                                          const std::vector<CalibrationObservation>& observations,
                                          const std::string& name, const CrossValidation* cv) {
  nlohmann::ordered_json j = profiles::json_of(base.document);
  j["name"] = name;
  j["description"] = "The paper's host (Athlon MP 2600+, 2133 MHz) with costs CALIBRATED by `rc2000sim calibrate` on "
                     "Table 2's software and single-pipeline columns only (docs/calibration.md), driver model " +
                     base.driver_model.name() + ". Each cost is the estimate of " + base.name +
                     ".json times its group's fitted factor.";
  auto scale_entry = [&](nlohmann::ordered_json& entry, CostGroup g) {
    const double estimate = entry.at("value").get<double>();
    const double factor = fit.scale[static_cast<int>(g)];
    char source[256];
    std::snprintf(source, sizeof source, "fitted: %.6g x the estimate %.6g s of %s.json (group %s)", factor, estimate,
                  base.name.c_str(), to_string(g).c_str());
    entry["value"] = estimate * factor;
    entry["source"] = source;
  };
  for (int k = 0; k < kHostWorkKinds; ++k) scale_entry(j["work_seconds"][to_string(HostWork(k))], group_of(HostWork(k)));
  for (int k = 0; k < kDriverWorkKinds; ++k) {
    nlohmann::ordered_json& entry = j["driver_seconds"][to_string(DriverWork(k))];
    if (used_by(DriverWork(k), base.driver_model.cost_unit)) {
      scale_entry(entry, group_of(DriverWork(k)));
    } else {
      entry["source"] = "not charged by this driver model (cost unit " +
                        std::string(to_string(base.driver_model.cost_unit)) + "): the estimate of " + base.name +
                        ".json, unfitted";
    }
  }
  scale_entry(j["driver_seconds"]["interrupt_latency"], CostGroup::DriverPass);

  nlohmann::ordered_json factors, rows = nlohmann::ordered_json::array();
  for (int g = 0; g < kCostGroups; ++g) factors[to_string(CostGroup(g))] = fit.scale[g];
  for (std::size_t i = 0; i < observations.size(); ++i) {
    nlohmann::ordered_json row = {{"run", observations[i].label},
                                  {"measured_seconds", observations[i].measured_seconds},
                                  {"fitted_seconds", fit.predicted_seconds[i]},
                                  {"relative_residual", fit.relative_residuals[i]}};
    if (cv != nullptr) row["left_out_relative_error"] = cv->relative_errors[i];
    rows.push_back(row);
  }
  j["calibration"] = {{"method", "non-negative least squares on relative residuals; one scale factor per cost group "
                                 "(docs/calibration.md)"},
                      {"data", "paper Table 2, software and single hardware pipeline columns (configs/paper-table2.json)"},
                      {"factors", factors},
                      {"rms_relative_residual", fit.rms_relative_residual}};
  if (cv != nullptr) {
    j["calibration"]["cross_validation"] = {{"method", "leave one out: each run predicted by the fit to the other " +
                                                          std::to_string(observations.size() - 1)},
                                            {"mean_absolute_relative_error", cv->mean_absolute},
                                            {"rms_relative_error", cv->rms},
                                            {"worst_relative_error", cv->worst}};
  }
  j["calibration"]["observations"] = rows;
  return j;
}

}  // namespace rc
