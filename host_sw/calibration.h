// Calibrating the host CPU cost model on measured run times (paper Table 2: the software and the
// single-pipeline columns only). A run's simulated time is linear in the host costs: in serial
// mode host work, driver work, PCI transfers and waiting for the board add up exactly. The costs
// are fitted as scale factors on groups of the first-principles estimates, one factor per group
// of terms that the data can tell apart (docs/calibration.md says why these groups).
#pragma once

#include <array>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "host_sw/host_cpu_model.h"

namespace rc {

enum class CostGroup : int {
  SoftwareTest,   // intersection_test: only the software column pays it
  Receiver,       // patch_scan, form_factor, energy_update, segment_setup: all scale with receivers
  Step,           // step
  DriverSegment,  // segment_pack, result_unpack: per segment, board runs only
  DriverPass,     // driver_call and interrupt latency: per pass, board runs only
  Count
};
constexpr int kCostGroups = static_cast<int>(CostGroup::Count);
std::string to_string(CostGroup group);

struct CalibrationObservation {
  std::string label;
  double measured_seconds = 0;
  std::array<double, kCostGroups> group_seconds{};  // simulated seconds per group under the profile used
  double fixed_seconds = 0;                         // PCI transfers and the board's own time
  double simulated_seconds() const;                 // fixed + sum of groups (scale 1)
};

// Splits a run's report (rc2000sim.software/1 or rc2000sim.board/1, serial) into groups.
CalibrationObservation observation_from_report(const std::string& label, double measured_seconds,
                                               const nlohmann::ordered_json& report, const HostProfile& used);

struct CalibrationFit {
  std::array<double, kCostGroups> scale{};  // >= 0; cost = scale x the profile's cost
  std::vector<double> predicted_seconds;
  std::vector<double> relative_residuals;   // (predicted - measured) / measured
  double rms_relative_residual = 0;
};

// Minimises the relative residuals (every scene counts alike, whether it took 1 s or 1000 s),
// with no negative cost. Throws std::invalid_argument without observations.
CalibrationFit fit_calibration(const std::vector<CalibrationObservation>& observations);

// The profile with every cost scaled by its group's factor, each value's source saying so, and
// the fit (method, observations, residuals) recorded beside it.
nlohmann::ordered_json calibrated_profile(const HostProfile& base, const CalibrationFit& fit,
                                          const std::vector<CalibrationObservation>& observations,
                                          const std::string& name);

}  // namespace rc
