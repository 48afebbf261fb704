// `rc2000sim paper`'s sec 5.6 per device (docs/board.md, "Sec 5.6"): for the XC2V6000, the Virtex-4
// SX55 and the Spartan-3 5000, the paper's rule at its clock (Table 1's 176.9 MHz; and, where the
// device's measured design clock differs, at that clock too) beside the model's best design from its
// own search under each stated board assumption (host_sw/studies/paper_design_search.h), in the same
// units; and the rooflines of the three devices. Rows, their JSON, CSV, printout and markdown.
#pragma once

#include <limits>
#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "board/throughput_estimates.h"
#include "host_sw/studies/paper_prediction.h"
#include "host_sw/studies/roofline.h"

namespace rc {

struct Sec56DeviceRow {
  board::PaperEstimate estimate;  // rule paper or model, its clock_assumption stated
  // Model rows (simulated on the paper's 280/4480 workload): the bound, run seconds and energy per test.
  std::string bound;
  std::string board;  // the stated board assumption
  double run_seconds = std::numeric_limits<double>::quiet_NaN();
  double nanojoules_per_test = std::numeric_limits<double>::quiet_NaN();
  std::size_t designs = 0, feasible = 0, simulated = 0;
};

std::vector<Sec56DeviceRow> sec56_device_rows(const PaperPrediction& prediction, double paper_software_rate,
                                              double model_software_rate);
std::vector<Roofline> sec56_rooflines(const PaperPrediction& prediction, double paper_software_rate);

// Lanes that fit at 15 bits on each sec 5.6 device under both sources of resources (the paper fit and
// the synthesis, pipeline/resource_source.h) side by side, with the synthesis rule's fit.
struct Sec56LanesBySource {
  std::vector<board::LanesBySource> devices;
  pipeline::SynthesisSliceFit fit;  // slices = per_lut * LUTs + per_flip_flop * FFs, and its leave-one-out errors
  std::string synthesizer;          // the synthesizer's version
};
Sec56LanesBySource sec56_lanes_by_source();
nlohmann::ordered_json lanes_by_source_json(const Sec56LanesBySource& lanes);
void print_lanes_by_source(const Sec56LanesBySource& lanes);
void lanes_by_source_markdown(std::ostream& md, const Sec56LanesBySource& lanes);

nlohmann::ordered_json sec56_devices_json(const std::vector<Sec56DeviceRow>& rows);
void print_sec56_devices(const std::vector<Sec56DeviceRow>& rows);
void sec56_devices_markdown(std::ostream& md, const std::vector<Sec56DeviceRow>& rows);

}  // namespace rc
