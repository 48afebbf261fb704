// design.json (schema rc2000sim.design/1; docs/design.md, docs/outputs.md): the one writer of a design
// search's document, which `rc2000sim design` writes and rc2000tlm.design() returns (python/), so
// both give the same fields in the same words.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "host_sw/studies/design_search.h"
#include "host_sw/studies/roofline.h"

namespace rc {

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

}  // namespace rc
