// Writing a study's outputs (docs/results/sweep.md): each scene's sweep.csv and sweep.json, and
// study.json beside them, then the summaries and the plots.
#pragma once

#include <string>

#include "apps/progress.h"
#include "host_sw/studies/sweep_study.h"

namespace rc {

// Before any work: every file the study will write can be written.
void expect_study_outputs(const Study& study, const std::string& out);

// study.json is written last: its presence means a complete study.
void write_study(const StudyResult& result, const std::string& out, const ProgressLine& clock);

}  // namespace rc
