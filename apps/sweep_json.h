// The sweep's JSON files: a scene's sweep.json (rc2000sim.sweep/1, docs/results/sweep.md) and the
// study record study.json beside it.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "apps/sweep_lanes_fit.h"
#include "host_sw/studies/sweep_study.h"

namespace rc {

// The software-only seconds of one width: a number when the width has one software time (one host),
// else an object by software key.
nlohmann::ordered_json software_at(const SceneSweep& scene, int bits);

nlohmann::ordered_json sweep_json(const Study& study, const SceneSweep& scene, const std::vector<SweptFit>& fits);

// One line per key and per row: the file stays as diff-able as the CSV and a third of dump(2)'s size.
std::string sweep_json_text(const nlohmann::ordered_json& sweep);

// The study as run and the tool that ran it, in every output folder.
std::string study_record(const StudyResult& result);

}  // namespace rc
