// The shard file (rc2000sim.shard/1, sweep_study.h's ShardResult) and back: the codec at the
// output edge. Numbers round-trip exactly.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "host_sw/studies/sweep_study.h"

namespace rc {

nlohmann::ordered_json shard_json(const ShardResult& shard);
ShardResult shard_from_json(const nlohmann::ordered_json& json, const std::string& origin);

}  // namespace rc
