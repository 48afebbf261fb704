// One table for a study over several scenes (docs/studies.md, "Outputs"): every scene's sweep rows,
// as write_sweep_csv gives them, under one header with a first column `scene` (the study's scene
// name, the folder each scene's own sweep.csv is in), scenes in the study's order. The rows are
// the per-scene files' rows unchanged, so the table joins back to them on scene and row order.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "host_sw/studies/sweep_study.h"

namespace rc {

// Writes the combined table. `extra` as for write_sweep_csv (the study's extra axis columns). A
// scene name holding a comma, a quote or a line break is quoted as RFC 4180 says.
void write_study_table_csv(std::ostream& out, const StudyResult& result, const std::vector<std::string>& extra = {});

}  // namespace rc
