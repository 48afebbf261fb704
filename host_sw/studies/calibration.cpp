#include "host_sw/studies/calibration.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "host_sw/studies/least_squares.h"

namespace rc {

std::string to_string(CostGroup group) {
  switch (group) {
    case CostGroup::SoftwareTest: return "software_test";
    case CostGroup::Receiver: return "receiver";
    case CostGroup::Step: return "step";
    case CostGroup::DriverData: return "driver_data";
    case CostGroup::DriverPass: return "driver_pass";
    case CostGroup::Count: break;
  }
  return "unknown";
}

CostGroup group_of(HostWork w) {
  switch (w) {
    case HostWork::IntersectionTest: return CostGroup::SoftwareTest;
    case HostWork::Step: return CostGroup::Step;
    default: return CostGroup::Receiver;
  }
}

CostGroup group_of(DriverWork w) { return w == DriverWork::Call ? CostGroup::DriverPass : CostGroup::DriverData; }

double minimum_scale(CostGroup group) { return group == CostGroup::DriverPass ? 1.0 : 0.0; }

double CalibrationObservation::simulated_seconds() const {
  double t = fixed_seconds;
  for (double s : group_seconds) t += s;
  return t;
}

CalibrationObservation observation_from_report(const std::string& label, double measured_seconds,
                                               const RunReport& report, const HostProfile& used) {
  CalibrationObservation o;
  o.label = label;
  o.measured_seconds = measured_seconds;
  for (int k = 0; k < kHostWorkKinds; ++k) o.group_seconds[static_cast<int>(group_of(HostWork(k)))] += report.work[k].seconds;
  if (report.board_run) {
    for (int k = 0; k < kDriverWorkKinds; ++k) {
      o.group_seconds[static_cast<int>(group_of(DriverWork(k)))] += report.board.driver[k].seconds;
    }
    // Each pass ends with one interrupt, whose latency the host profile sets; the rest of the
    // waiting is the board's own time.
    const double irq = used.interrupt_latency.to_seconds() * static_cast<double>(report.board.batching.passes);
    o.group_seconds[static_cast<int>(CostGroup::DriverPass)] += irq;
    o.fixed_seconds = report.time.pci_transfer + report.time.waiting - irq;
  }
  return o;
}

CalibrationFit fit_calibration(const std::vector<CalibrationObservation>& observations) {
  if (observations.empty()) throw std::invalid_argument("calibration needs observations");
  LeastSquaresProblem p;
  for (const CalibrationObservation& o : observations) {
    if (!(o.measured_seconds > 0)) throw std::invalid_argument("observation '" + o.label + "' has no measured time");
    std::vector<double> row(kCostGroups);
    for (int g = 0; g < kCostGroups; ++g) row[g] = o.group_seconds[g] / o.measured_seconds;
    double target = (o.measured_seconds - o.fixed_seconds) / o.measured_seconds;
    for (int g = 0; g < kCostGroups; ++g) target -= minimum_scale(CostGroup(g)) * row[g];  // x = floor + y, y >= 0
    p.rows.push_back(row);
    p.targets.push_back(target);
  }
  const LeastSquaresSolution s = solve_nonnegative_least_squares(p);
  CalibrationFit fit;
  double squares = 0;
  for (int g = 0; g < kCostGroups; ++g) fit.scale[g] = minimum_scale(CostGroup(g)) + s.x[g];
  for (const CalibrationObservation& o : observations) {
    double t = o.fixed_seconds;
    for (int g = 0; g < kCostGroups; ++g) t += fit.scale[g] * o.group_seconds[g];
    fit.predicted_seconds.push_back(t);
    fit.relative_residuals.push_back((t - o.measured_seconds) / o.measured_seconds);
    squares += fit.relative_residuals.back() * fit.relative_residuals.back();
  }
  fit.rms_relative_residual = std::sqrt(squares / observations.size());
  return fit;
}

std::string fit_problem(const CalibrationFit& fit, const std::vector<CalibrationObservation>& observations) {
  char text[512];
  if (!(fit.rms_relative_residual <= kMaxFitRmsResidual)) {
    std::snprintf(text, sizeof text,
                  "the fit misses its %zu runs by %.3g%% rms (at most %.0f%%: kMaxFitRmsResidual, "
                  "docs/calibration.md): the table's times are not what this model of the host can produce",
                  observations.size(), 100 * fit.rms_relative_residual, 100 * kMaxFitRmsResidual);
    return text;
  }
  for (int g = 0; g < kCostGroups; ++g) {
    double paid = 0;
    for (const CalibrationObservation& o : observations) paid += o.group_seconds[g];
    if (paid > 0 && fit.scale[g] == 0) {
      std::snprintf(text, sizeof text,
                    "the fit sets every cost of group %s to 0 s (the non-negativity bound), though the runs pay it: "
                    "the table's times are shorter than the rest of the model explains",
                    to_string(CostGroup(g)).c_str());
      return text;
    }
  }
  return "";
}

CrossValidation cross_validate(const std::vector<CalibrationObservation>& observations) {
  if (observations.size() < 2) throw std::invalid_argument("cross-validation needs at least two observations");
  CrossValidation cv;
  double squares = 0, absolute = 0;
  for (std::size_t left_out = 0; left_out < observations.size(); ++left_out) {
    std::vector<CalibrationObservation> rest;
    for (std::size_t i = 0; i < observations.size(); ++i) {
      if (i != left_out) rest.push_back(observations[i]);
    }
    const CalibrationFit fit = fit_calibration(rest);
    const CalibrationObservation& o = observations[left_out];
    double predicted = o.fixed_seconds;
    for (int g = 0; g < kCostGroups; ++g) predicted += fit.scale[g] * o.group_seconds[g];
    const double error = (predicted - o.measured_seconds) / o.measured_seconds;
    cv.relative_errors.push_back(error);
    squares += error * error;
    absolute += std::fabs(error);
    cv.worst = std::max(cv.worst, std::fabs(error));
  }
  cv.mean_absolute = absolute / observations.size();
  cv.rms = std::sqrt(squares / observations.size());
  return cv;
}

}  // namespace rc
