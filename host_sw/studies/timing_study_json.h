// What a timing study's worker process sends its parent (timing_study.cpp): its outcomes, each report
// through run_report_json.h's codec, or the error that stopped it. Internal to one study.
#pragma once

#include <string>
#include <vector>

#include "host_sw/studies/timing_study.h"

namespace rc {

struct WorkerAnswer {
  std::string error;  // empty when the worker ran its shard
  std::vector<TimingOutcome> outcomes;
};

std::string encode_worker_answer(const WorkerAnswer& answer);
// Throws std::invalid_argument on a malformed text.
WorkerAnswer decode_worker_answer(const std::string& text);

}  // namespace rc
