// A sweep row as a JSON record (sweep.json's rows, the shard file's) and back: the codec at the
// output edge; the columns are sweep_columns.h's.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "host_sw/studies/sweep_row.h"

namespace rc {

nlohmann::ordered_json sweep_row_json(const SweepRow& row, const std::vector<std::string>& extra = {});
// The longest simulated time a row read back may hold: 1e12 s (31,700 years). No configuration the
// model finishes simulating comes near it (the slowest shipped study row takes minutes of simulated
// time); a figure there is a damaged or edited shard, and 1e308 would overflow every sum over rows.
constexpr double kMaxRowSeconds = 1e12;

// The numbers and texts of a row back from sweep_row_json; the configuration is `config` (the
// plan's), and the row's own config columns must agree with it (std::invalid_argument otherwise), as
// must its figures: finite, not negative, a simulated row's time in (0, kMaxRowSeconds], shares at
// most 1 (std::invalid_argument naming the row and the key).
SweepRow sweep_row_from_json(const nlohmann::ordered_json& json, const SweepConfig& config);

}  // namespace rc
