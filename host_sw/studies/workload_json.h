// A workload (workload.h) as report.json and sweep.json record it ("workload", docs/outputs.md):
// the codec at the output edge; nothing reads it back.
#pragma once

#include <cstdint>

#include <nlohmann/json.hpp>

#include "host_sw/studies/workload.h"

namespace rc {

// `faces` and `patches`: what the scene came out with; `steps`: the steps solved (0: not yet known).
nlohmann::ordered_json workload_json(const Workload& workload, std::uint64_t faces, std::uint64_t patches, int steps);

}  // namespace rc
