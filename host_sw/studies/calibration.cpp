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

namespace {

CostGroup group_of(HostWork w) {
  switch (w) {
    case HostWork::IntersectionTest: return CostGroup::SoftwareTest;
    case HostWork::Step: return CostGroup::Step;
    default: return CostGroup::Receiver;
  }
}

CostGroup group_of(DriverWork w) { return w == DriverWork::Call ? CostGroup::DriverPass : CostGroup::DriverData; }

}  // namespace

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
  nlohmann::ordered_json j = base.json;
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
