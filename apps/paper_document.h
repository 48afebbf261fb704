// What `rc2000sim paper` writes, as typed data: the prediction's rows and what the command knows
// (profiles, file names). Its writers (paper.json, paper.csv in paper_command.cpp; paper.md in
// paper_markdown.cpp) read these fields, never each other's output.
#pragma once

#include <string>
#include <vector>

#include "apps/paper_sec56.h"
#include "host_sw/energy/full_rate_energy.h"
#include "host_sw/studies/paper_prediction.h"

namespace rc {

struct PaperDocument {
  std::vector<PaperTableRow> rows;
  std::vector<board::PaperEstimate> paper_rule, model;  // sec 5.6, pairwise
  std::vector<BankVariantRow> bank_variants;
  // Sec 5.6 in joules: each model estimate of the throughput table that has lanes (the same designs),
  // priced per intersection at full rate (host_sw/energy/full_rate_energy.h).
  std::vector<energy::FullRateEnergy> energy;
  // Sec 5.6 per device: the paper's rule at its clock(s) and the model's searched designs (apps/paper_sec56.h).
  std::vector<Sec56DeviceRow> devices;
  std::vector<Roofline> rooflines;
  // Lanes that fit on the three devices under both sources of resources, and the source the model's
  // searches above used (--resources).
  Sec56LanesBySource lanes_by_source;
  pipeline::ResourceSource resources = pipeline::ResourceSource::paper_fit;
  PaperSummary summary;
  std::string host_profile;  // as given to --host
  std::string driver_model;  // the host profile's
  std::string variants;      // the variants file, relative to the source tree when inside it
  // The prediction intervals' calibration part (PaperPrediction::left_out_error_*).
  double left_out_error_low = 0, left_out_error_high = 0;
  std::size_t left_out_errors = 0;
};

std::string paper_markdown(const PaperDocument& document);  // docs/results/paper.md

}  // namespace rc
