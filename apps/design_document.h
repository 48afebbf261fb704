// What `rc2000sim design` writes and prints (docs/design.md, docs/outputs.md) beside design.json
// (host_sw/studies/design_json.h): design.csv, design.md and the summary, from one search result.
#pragma once

#include <string>

#include "host_sw/studies/design_json.h"
#include "host_sw/studies/design_options.h"

namespace rc {

std::string design_csv(const DesignSearchResult& result);        // one row per simulated design
std::string design_markdown(const DesignDocument& doc);
void print_design(const DesignDocument& doc);

}  // namespace rc
