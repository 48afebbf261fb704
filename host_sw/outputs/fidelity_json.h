// The output edge of a run's fidelity sample (host_sw/visibility/decision_sample.h): report.json's
// "fidelity" section (docs/outputs.md).
#pragma once

#include <nlohmann/json.hpp>

#include "host_sw/visibility/decision_sample.h"

namespace rc {

// `warn_share`: the run's --fidelity-warn; `warning`: what it printed ("" for none).
nlohmann::ordered_json fidelity_json(const Fidelity& f, double warn_share, const std::string& warning);

}  // namespace rc
