#include "host_sw/studies/paper_calibration.h"

#include "host_sw/studies/timing_study.h"

namespace rc {

namespace {

// Per scene the software run, then every variant's single-pipeline run of every scene.
std::vector<TimingCase> calibration_cases(const std::vector<PaperScene>& scenes, const HostProfile& base,
                                          const std::vector<HostProfile>& variants) {
  std::vector<TimingCase> cases;
  for (const PaperScene& s : scenes) {
    TimingCase c = paper_timing_case(s, PaperImplementation::Software, base.name);
    c.host_profile = base;
    cases.push_back(c);
  }
  for (const HostProfile& v : variants) {
    for (const PaperScene& s : scenes) {
      TimingCase c = paper_timing_case(s, PaperImplementation::OnePipe, base.name);
      c.label += " " + v.driver_model.name();
      c.board.host_profile = v;
      cases.push_back(c);
    }
  }
  return cases;
}

}  // namespace

PaperCalibration calibrate_on_paper(const std::vector<PaperScene>& scenes, const HostProfile& base) {
  std::vector<HostProfile> variants;
  for (const DriverModel& m : serial_driver_variants(base.driver_model)) variants.push_back(with_driver_model(base, m));
  const std::vector<TimingCase> cases = calibration_cases(scenes, base, variants);
  const std::vector<TimingOutcome> outcomes = run_timing_study(cases);

  PaperCalibration result;
  result.simulated_runs = cases.size();
  const std::size_t n = scenes.size();
  for (std::size_t v = 0; v < variants.size(); ++v) {
    std::vector<CalibrationObservation> observations;
    for (std::size_t i = 0; i < n; ++i) {
      const PaperRow& row = scenes[i].row;
      observations.push_back(
          observation_from_report(row.label() + " software", row.software_seconds, outcomes[i].report, base));
      observations.push_back(observation_from_report(row.label() + " one_pipe", row.one_pipe_seconds,
                                                     outcomes[n + v * n + i].report, variants[v]));
    }
    result.variants.push_back(calibrate_variant(variants[v], std::move(observations)));
  }
  result.chosen = best_by_cross_validation(result.variants);
  return result;
}

}  // namespace rc
