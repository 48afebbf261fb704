// Calibrating the host CPU cost model on measured run times (paper Table 2: the software and the
// single-pipeline columns only). A run's simulated time is linear in the host costs: in serial
// mode host work, driver work, PCI transfers and waiting for the board add up exactly. The costs
// are fitted as scale factors on groups of the first-principles estimates, one factor per group
// of terms that the data can tell apart (docs/calibration.md says why these groups).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "host_sw/driver/host_cpu_model.h"
#include "host_sw/platform/run_report.h"

namespace rc {

enum class CostGroup : int {
  SoftwareTest,   // intersection_test: only the software column pays it
  Receiver,       // patch_scan, form_factor, energy_update, segment_setup: all scale with receivers
  Step,           // step
  DriverData,     // the driver's per-datum CPU work, board runs only: segment_pack, result_unpack and
                  // face_pack (per_segment), or coordinate_convert, word_store, word_load (per_word)
  DriverPass,     // driver_call and interrupt latency: per pass, board runs only
  Count
};
constexpr int kCostGroups = static_cast<int>(CostGroup::Count);
std::string to_string(CostGroup group);
// The group each cost is fitted in (docs/calibration.md says why these groups).
CostGroup group_of(HostWork work);
CostGroup group_of(DriverWork work);

struct CalibrationObservation {
  std::string label;
  double measured_seconds = 0;
  std::array<double, kCostGroups> group_seconds{};  // simulated seconds per group under the profile used
  double fixed_seconds = 0;                         // PCI transfers and the board's own time
  double simulated_seconds() const;                 // fixed + sum of groups (scale 1)
};

// Splits a run's report (software or serial board) into groups.
CalibrationObservation observation_from_report(const std::string& label, double measured_seconds,
                                               const RunReport& report, const HostProfile& used);

struct CalibrationFit {
  std::array<double, kCostGroups> scale{};  // >= 0; cost = scale x the profile's cost
  std::vector<double> predicted_seconds;
  std::vector<double> relative_residuals;   // (predicted - measured) / measured
  double rms_relative_residual = 0;
};

// The least factor a group may take. Every calibration run has one pass per step, so per-pass and
// per-step costs cannot be told apart; the software column pins the step, and the per-pass group
// (a driver entry, an interrupt's latency) is held at or above its first-principles estimate,
// which is the physical floor of a 2004 Windows driver round trip, instead of being fitted to zero.
double minimum_scale(CostGroup group);

// Minimises the relative residuals (every scene counts alike, whether it took 1 s or 1000 s),
// with no cost below minimum_scale. Throws std::invalid_argument without observations.
CalibrationFit fit_calibration(const std::vector<CalibrationObservation>& observations);

// The most a calibrated profile may miss its own data by: the rms relative residual of the fit. The
// shipped fits of Table 2 miss by 1.9% to 4.8% (docs/calibration.md); a fit five times worse than
// the worst of them does not describe the runs, whatever it is written as.
constexpr double kMaxFitRmsResidual = 0.25;

// Why `fit` must not become a profile, or "" when it may: its rms relative residual is above
// kMaxFitRmsResidual, or a cost group the observations pay was fitted to zero (the non-negativity
// bound: the measured times are shorter than the rest of the model explains, so a cost of 0 s is
// the fit giving up, not a measurement). `calibrate` refuses such a fit and writes nothing.
std::string fit_problem(const CalibrationFit& fit, const std::vector<CalibrationObservation>& observations);

// Leave-one-out cross-validation: each observation predicted by the fit to all the others.
struct CrossValidation {
  std::vector<double> relative_errors;  // (prediction - measured) / measured, per observation
  double mean_absolute = 0;             // mean of |relative error|
  double rms = 0;
  double worst = 0;                     // largest |relative error|
};
// Needs at least two observations (throws std::invalid_argument).
CrossValidation cross_validate(const std::vector<CalibrationObservation>& observations);

}  // namespace rc
