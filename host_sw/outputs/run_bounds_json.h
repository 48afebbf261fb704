// The bound model of a board run (run_bounds.h) as report.json writes it: board.bounds
// (docs/outputs.md). The codec at the output edge; nothing reads it back.
#pragma once

#include <nlohmann/json.hpp>

#include "host_sw/platform/run_bounds.h"

namespace rc {

nlohmann::ordered_json run_bounds_json(const RunBounds& bounds);

}  // namespace rc
