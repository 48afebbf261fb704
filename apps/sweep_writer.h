// Writing a study's outputs (docs/results/sweep.md): each scene's sweep.csv and sweep.json, and
// study.json beside them, then the summaries and the plots.
#pragma once

#include <string>
#include <vector>

#include "apps/progress.h"
#include "host_sw/studies/sweep_study.h"

namespace rc {

// Before any work: every file the study will write can be written.
void expect_study_outputs(const Study& study, const std::string& out);

// study.json is written last: its presence means a complete study. `out` is the command's folder
// (Outputs::own_folder): `listing_set` and `keep` as there (sweep merge into its shards' folder).
void write_study(const StudyResult& result, const std::string& out, const ProgressLine& clock,
                 const std::string& listing_set = "", const std::vector<std::string>& keep = {});

// The listing set of a study's shards (Outputs::own_folder): the shards of one study split one way
// add to their folder's listing instead of replacing each other.
std::string shard_listing_set(const Study& study, unsigned count);

}  // namespace rc
