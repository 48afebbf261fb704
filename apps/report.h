// Machine-readable outputs of a run: report.json (keys documented in docs/outputs.md) and
// patches.csv (one row per patch), as text.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "board/throughput_estimates.h"
#include "host_sw/driver/host_cpu_model.h"
#include "pipeline/float_format.h"
#include "host_sw/radiosity/radiosity.h"
#include "scenes/scene.h"

namespace rc {

nlohmann::ordered_json scene_json(const Scene& scene, const std::string& source,
                                  const std::vector<std::string>& warnings);
nlohmann::ordered_json solver_json(const SolverResult& result);
// The text of the files (apps/outputs.h writes them): JSON indented by two, and patches.csv.
std::string pretty_json(const nlohmann::ordered_json& json);
std::string patches_csv(const Scene& scene, const std::vector<Spectrum>& radiosity);

// One sec 5.6 estimate (board/throughput_estimates.h), as paper.json, report.json and sweep.json
// write it.
nlohmann::ordered_json estimate_json(const board::PaperEstimate& estimate);

// "Lanes that fit" on `device` under the paper's rule and the model's, with why they differ: what a
// board run's or a sweep's device would do at full rate (docs/calibration.md, "Sec 5.6"). The paper
// rule's software rate is Table 2's peak; the model's is `host`'s intersection test.
// Sec 5.6's estimates ask the device profile for every lane count up to what fits; a profile that
// gives no clock for some count (no clock.mhz_default) cannot be estimated, which must not fail a run
// or sweep that never uses that count: `missing` then says why, naming the profile and key.
struct LanesThatFit {
  board::PaperEstimate paper_rule, model;
  std::string missing;  // "": estimated
};
LanesThatFit lanes_that_fit(const std::string& device, const std::string& host, int bits);
// `resources`: the model's source of slices and block multipliers (the paper's rule has its own).
LanesThatFit lanes_that_fit(const board::DeviceProfile& device, const HostProfile& host, int bits,
                            pipeline::ResourceSource resources = pipeline::ResourceSource::paper_fit);
// Float lanes (estimates, docs/pipeline.md): the model's estimate for `format`; the paper's rule is its own.
LanesThatFit lanes_that_fit(const board::DeviceProfile& device, const HostProfile& host, pipeline::FloatFormat format);
nlohmann::ordered_json lanes_that_fit_json(const LanesThatFit& estimates);
std::string lanes_that_fit_line(const LanesThatFit& estimates);  // one line for a summary

}  // namespace rc
