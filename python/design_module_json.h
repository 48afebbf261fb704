// rc2000tlm.design() and rc2000tlm.design_defaults() on the C++ side (design_module_json.cpp).
#pragma once

#include <string>

namespace rc {

// The design search of `rc2000sim design` with the options given (a JSON object of the command's
// options in snake_case); design.json's document (without the run command, which names an output
// folder's files) and the best design's device profile, as JSON text.
std::string design_search(const std::string& options_json, bool progress);
// Every option's default (null where the command's rule applies: 1 .. the lanes that fit, ...).
std::string design_defaults();

}  // namespace rc
