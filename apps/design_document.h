// What `rc2000sim design` writes and prints (docs/design.md, docs/outputs.md): design.json, design.csv,
// design.md and the summary, from one search result.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "host_sw/studies/design_search.h"
#include "host_sw/studies/roofline.h"

namespace rc {

// `rc2000sim run --banks` takes 1..64: a design the search reports must be one run can reproduce.
inline constexpr unsigned kMaxRunBanks = 64;

struct DesignDocument {
  const DesignSearchResult& result;
  const DesignSpace& space;
  const DesignConstraints& constraints;
  const Roofline& roofline;
  std::string out_dir;
  std::string command;  // the command line that made it
};

// The `rc2000sim run --impl board` command that simulates `point` on the search's workload and gives its
// figures (its device profile written as <out_dir>/<profile_file>).
std::string run_command(const DesignDocument& doc, const DesignPoint& point, const std::string& profile_file);

nlohmann::ordered_json design_json(const DesignDocument& doc);  // schema rc2000sim.design/1
std::string design_csv(const DesignSearchResult& result);        // one row per simulated design
std::string design_markdown(const DesignDocument& doc);
void print_design(const DesignDocument& doc);

}  // namespace rc
