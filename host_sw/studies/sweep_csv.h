// sweep.csv (docs/results/sweep.md): one line per sweep row, the columns of sweep_columns.h.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "host_sw/studies/sweep_row.h"

namespace rc {

// The CSV header and rows (stable column names; numbers with enough digits to round-trip).
void write_sweep_csv(std::ostream& out, const std::vector<SweepRow>& rows, const std::vector<std::string>& extra = {});

}  // namespace rc
