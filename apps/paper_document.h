// What `rc2000sim paper` writes, as typed data: the prediction's rows and what the command knows
// (profiles, file names). Its writers (paper.json, paper.csv in paper_command.cpp; paper.md in
// paper_markdown.cpp) read these fields, never each other's output.
#pragma once

#include <string>
#include <vector>

#include "host_sw/energy/full_rate_energy.h"
#include "host_sw/studies/paper_prediction.h"

namespace rc {

struct PaperDocument {
  std::vector<PaperTableRow> rows;
  std::vector<board::PaperEstimate> paper_rule, model;  // sec 5.6, pairwise
  std::vector<BankVariantRow> bank_variants;
  // Sec 5.6 in joules: each model estimate with lanes, and the XC2V6000's own lanes that fit, priced
  // per intersection at full rate (host_sw/energy/full_rate_energy.h).
  std::vector<energy::FullRateEnergy> energy;
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
