// The resolved study as recorded (schema rc2000sim.study/1, in every output folder and shard) and
// back: the codec at the output edge for study.h's Study.
#pragma once

#include <nlohmann/json.hpp>

#include "host_sw/studies/study.h"

namespace rc {

// study_from_json resolves the profile paths again and runs check_study.
nlohmann::ordered_json study_json(const Study& study);
Study study_from_json(const nlohmann::ordered_json& json);

}  // namespace rc
